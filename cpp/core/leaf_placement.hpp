// Where a leaf's page coordinates land in the world and which image texel each side shows, for each
// spine position and for mirrored (backward) turns. Pure math shared by the renderer and the tests.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "book.hpp"

namespace conecurl {

struct LeafPlacement {
    glm::dmat4 pageToWorld;  // curled page space (x from the spine, y along it, z up) to world
    double handedness;       // +1, or -1 where pageToWorld mirrors
    // Texture coordinates (u right, v down the image) from (x / width, y / height, 1), per side as
    // the viewer sees it: `facing` for the side up in page space (+z), `away` for the other.
    glm::dmat3 facingUv;
    glm::dmat3 awayUv;
    bool facingIsBackPage;   // true for mirrored leaves: their +z side is the leaf's back page
};

// `flippedY` poses the curl from the other end of the spine (a drag from the top corner): page point
// (x, y) of the curl is the leaf's point (x, pageHeight - y).
LeafPlacement placeLeaf(Binding binding, bool mirrored, double pageHeight, bool flippedY = false);

// The camera's target: centre and half extents, in world units, of what the view must show.
struct ViewFrame {
    glm::dvec2 center;
    glm::dvec2 halfExtent;
};

ViewFrame viewFrameFor(Display display, Binding binding, double pageWidth, double pageHeight);

// Unit world vector from the spine towards the side where unturned leaves lie.
glm::dvec2 unturnedSide(Binding binding);

// World position of page point (x, y) of a leaf drawn as `draw`: the C++ reference of the shader.
glm::dvec3 leafPointToWorld(const LeafDraw& draw, Binding binding, double pageHeight,
                            glm::dvec2 pagePoint);

// World normal of the leaf's +z side (page space) there: the side whose texture is `facingUv`'s.
glm::dvec3 leafNormalToWorld(const LeafDraw& draw, Binding binding, double pageHeight, glm::dvec2 pagePoint);

}  // namespace conecurl
