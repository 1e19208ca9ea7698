// Placement tables for the three spine positions; see leaf_placement.hpp.
#include "leaf_placement.hpp"

#include "cone_deform.hpp"

namespace conecurl {
namespace {

// Columns are (s, r, 1) -> (u, v): GLM matrices are column-major.
glm::dmat3 uvMap(double us, double ur, double u0, double vs, double vr, double v0) {
    return glm::dmat3(glm::dvec3(us, vs, 0.0), glm::dvec3(ur, vr, 0.0), glm::dvec3(u0, v0, 1.0));
}

}  // namespace

LeafPlacement placeLeaf(Binding binding, bool mirrored, double h, bool flippedY) {
    // Page point (x, y, z) -> world, centred on the middle of the spine.
    glm::dmat4 m(1.0);
    glm::dmat3 frontUv;
    glm::dmat3 backUv;
    double handedness = 1.0;
    switch (binding) {
        case Binding::Left:  // world (x, y - h/2, z)
            m[3] = glm::dvec4(0.0, -0.5 * h, 0.0, 1.0);
            frontUv = uvMap(1, 0, 0, 0, -1, 1);   // (s, 1 - r)
            backUv = uvMap(-1, 0, 1, 0, -1, 1);   // (1 - s, 1 - r): reads right once turned
            break;
        case Binding::Right:  // world (-x, y - h/2, z)
            m[0] = glm::dvec4(-1.0, 0.0, 0.0, 0.0);
            m[3] = glm::dvec4(0.0, -0.5 * h, 0.0, 1.0);
            handedness = -1.0;
            frontUv = uvMap(-1, 0, 1, 0, -1, 1);  // (1 - s, 1 - r)
            backUv = uvMap(1, 0, 0, 0, -1, 1);    // (s, 1 - r)
            break;
        case Binding::Top:  // world (y - h/2, -x, z): the leaf hangs below the spine, turns up over it
            m[0] = glm::dvec4(0.0, -1.0, 0.0, 0.0);
            m[1] = glm::dvec4(1.0, 0.0, 0.0, 0.0);
            m[3] = glm::dvec4(-0.5 * h, 0.0, 0.0, 1.0);
            frontUv = uvMap(0, 1, 0, 1, 0, 0);    // (r, s): image top at the spine
            backUv = uvMap(0, 1, 0, -1, 0, 1);    // (r, 1 - s): upright once flipped up
            break;
    }
    if (mirrored) {
        glm::dmat4 flipX(1.0);
        flipX[0][0] = -1.0;
        m = m * flipX;
        handedness = -handedness;
    }
    if (flippedY) {
        // Page point (x, y) of the curl is the leaf's point (x, h - y): the cone, whose apex lies below
        // y = 0, then lifts the corner at the far end of the spine. The +z side stays the +z side.
        glm::dmat4 flipY(1.0);
        flipY[1][1] = -1.0;
        flipY[3][1] = h;
        m = m * flipY;
        handedness = -handedness;
        const glm::dmat3 flipV = uvMap(1, 0, 0, 0, -1, 1);  // (s, r) -> (s, 1 - r)
        frontUv = frontUv * flipV;
        backUv = backUv * flipV;
    }
    // Mirrored page space has the leaf's back page on its +z side: the same physical point, the
    // same texel, only which side faces up swaps.
    return LeafPlacement{m, handedness, mirrored ? backUv : frontUv, mirrored ? frontUv : backUv, mirrored};
}

ViewFrame viewFrameFor(Display display, Binding binding, double w, double h) {
    const bool single = display == Display::Single;
    switch (binding) {
        case Binding::Left:
            return single ? ViewFrame{{0.5 * w, 0.0}, {0.5 * w, 0.5 * h}} : ViewFrame{{0.0, 0.0}, {w, 0.5 * h}};
        case Binding::Right:
            return single ? ViewFrame{{-0.5 * w, 0.0}, {0.5 * w, 0.5 * h}} : ViewFrame{{0.0, 0.0}, {w, 0.5 * h}};
        case Binding::Top:
            return single ? ViewFrame{{0.0, -0.5 * w}, {0.5 * h, 0.5 * w}} : ViewFrame{{0.0, 0.0}, {0.5 * h, w}};
    }
    return ViewFrame{{0.0, 0.0}, {w, 0.5 * h}};
}

glm::dvec2 unturnedSide(Binding binding) {
    // Page x (away from the spine) in world, as placeLeaf lays an unturned leaf.
    switch (binding) {
        case Binding::Left: return {1.0, 0.0};
        case Binding::Right: return {-1.0, 0.0};
        case Binding::Top: return {0.0, -1.0};
    }
    return {1.0, 0.0};
}

glm::dvec3 leafPointToWorld(const LeafDraw& draw, Binding binding, double h, glm::dvec2 q) {
    const LeafPlacement placement = placeLeaf(binding, draw.mirrored, h, draw.flippedY);
    const glm::dvec3 p = curlPoint(q, draw.curl);
    return glm::dvec3(placement.pageToWorld * glm::dvec4(p, 1.0));
}

glm::dvec3 leafNormalToWorld(const LeafDraw& draw, Binding binding, double h, glm::dvec2 q) {
    const LeafPlacement placement = placeLeaf(binding, draw.mirrored, h, draw.flippedY);
    // A normal found in page space belongs to the +z side; a mirror moves it but keeps it on that side.
    return glm::dmat3(placement.pageToWorld) * curlNormalAnalytic(q, draw.curl);
}

}  // namespace conecurl
