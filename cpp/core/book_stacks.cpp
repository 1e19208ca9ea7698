// The stacks' depth rule and their edge faces; see book_stacks.hpp.
#include "book_stacks.hpp"

#include <algorithm>
#include <cmath>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/geometric.hpp>

#include "leaf_placement.hpp"

namespace conecurl {

StackLeaves stackLeaves(const Book& book) {
    // Each stack holds every leaf from its end of the book up to its top (Book::stackTop: the leaves in
    // flight, and those a riffling leaf carries, lie between the two tops). In single display a
    // position is a page, and a page is a leaf: the same counting either way.
    const int count = book.leafCount();
    const int turnedTop = book.stackTop(true);
    const int unturnedTop = book.stackTop(false);
    StackLeaves out;
    out.turned = turnedTop + 1;
    out.unturned = count - unturnedTop;
    out.turnedTopHard = out.turned > 0 && book.isHardLeaf(turnedTop);
    out.turnedBottomHard = out.turned > 0 && book.isHardLeaf(0);
    out.unturnedTopHard = out.unturned > 0 && book.isHardLeaf(unturnedTop);
    out.unturnedBottomHard = out.unturned > 0 && book.isHardLeaf(count - 1);
    return out;
}

StackDepth stackDepth(int leaves, bool topHard, bool bottomHard, double leafThicknessOfWidth, double pageWidth) {
    StackDepth depth;
    if (leaves <= 0 || !(leafThicknessOfWidth > 0.0) || !(pageWidth > 0.0)) return depth;
    const double board = kBoardThicknessOfWidth * pageWidth;
    if (topHard) depth.topBoard = board;
    // One leaf is the top and the bottom at once: its board counts once.
    if (bottomHard && leaves > (topHard ? 1 : 0)) depth.bottomBoard = board;
    const int paperLeaves = leaves - (depth.topBoard > 0.0 ? 1 : 0) - (depth.bottomBoard > 0.0 ? 1 : 0);
    if (paperLeaves > 0) {
        const double raw = paperLeaves * leafThicknessOfWidth * pageWidth;
        const double cap = kMaxPaperDepthOfWidth * pageWidth;
        depth.paper = raw / std::sqrt(1.0 + (raw / cap) * (raw / cap));
        depth.leafThickness = depth.paper / paperLeaves;
    }
    return depth;
}

double singleStackRoom(const BookConfig& config) {
    return 0.5 * (kSingleFrameMargin - 1.0) * std::min(config.pageWidth, config.pageHeight);
}

namespace {

// `depth` squeezed, every layer alike, to at most `room`.
StackDepth fitted(StackDepth depth, double room) {
    const double total = depth.total();
    if (!(total > room)) return depth;
    const double k = room / total;
    depth.topBoard *= k;
    depth.paper *= k;
    depth.bottomBoard *= k;
    depth.leafThickness *= k;
    return depth;
}

}  // namespace

Stacks bookStacks(const BookConfig& config, const StackLeaves& leaves, double leafThicknessOfWidth) {
    const double w = config.pageWidth;
    Stacks stacks{stackDepth(leaves.turned, leaves.turnedTopHard, leaves.turnedBottomHard, leafThicknessOfWidth, w),
                  stackDepth(leaves.unturned, leaves.unturnedTopHard, leaves.unturnedBottomHard, leafThicknessOfWidth, w)};
    if (config.display == Display::Single) {
        const double room = singleStackRoom(config);
        stacks.turned = fitted(stacks.turned, room);
        stacks.unturned = fitted(stacks.unturned, room);
    }
    return stacks;
}

namespace {

// One stack's faces: page points (x from the spine, y along it) of the flat leaf, turned or not, to the
// world, `depth` below the table plane.
void addStack(std::vector<float>& out, const BookConfig& c, const StackDepth& depth, bool turned) {
    const LeafPlacement placement = placeLeaf(c.binding, false, c.pageHeight);
    const double w = c.pageWidth;
    const double h = c.pageHeight;
    auto world = [&](double x, double y, double d) {
        // A turned leaf lies rotated by pi about the spine: page x runs the other way.
        const glm::dvec4 p = placement.pageToWorld * glm::dvec4(turned ? -x : x, y, 0.0, 1.0);
        return glm::dvec3(p.x, p.y, -d);
    };
    auto quad = [&](const glm::dvec3 (&q)[4], double sTop, double sBottom) {
        glm::dvec3 n = glm::normalize(glm::cross(q[1] - q[0], q[3] - q[0]));
        if (n.z < 0.0) n = -n;  // the side that faces up and out, towards the eye
        const double s[4] = {sTop, sTop, sBottom, sBottom};
        for (const int i : {0, 1, 2, 0, 2, 3}) {
            const float v[kStackVertexFloats] = {static_cast<float>(q[i].x), static_cast<float>(q[i].y),
                                                 static_cast<float>(q[i].z), static_cast<float>(s[i]),
                                                 static_cast<float>(n.x), static_cast<float>(n.y),
                                                 static_cast<float>(n.z), 0.0f};
            out.insert(out.end(), v, v + kStackVertexFloats);
        }
    };
    // Layers from the top: [a, b] in depth, and s at each end.
    auto layer = [&](double a, double b, double sA, double sB) {
        if (!(b > a)) return;
        // Each outline at depth d is the page grown by d on its three free sides (a 45 degree bevel).
        const glm::dvec3 fore[4] = {world(w + a, -a, a), world(w + a, h + a, a), world(w + b, h + b, b), world(w + b, -b, b)};
        const glm::dvec3 head[4] = {world(0.0, h + a, a), world(w + a, h + a, a), world(w + b, h + b, b), world(0.0, h + b, b)};
        const glm::dvec3 tail[4] = {world(0.0, -a, a), world(w + a, -a, a), world(w + b, -b, b), world(0.0, -b, b)};
        quad(fore, sA, sB);
        quad(head, sA, sB);
        quad(tail, sA, sB);
    };
    const double paperTop = depth.topBoard;
    const double paperBottom = paperTop + depth.paper;
    layer(0.0, paperTop, -1.0, -1.0);
    const double leaves = depth.leafThickness > 0.0 ? depth.paper / depth.leafThickness : 0.0;
    layer(paperTop, paperBottom, 0.0, leaves);
    layer(paperBottom, depth.total(), -1.0, -1.0);
}

}  // namespace

std::vector<float> stackMesh(const BookConfig& config, const Stacks& stacks) {
    std::vector<float> out;
    // In single display the turned side lies outside the view, as in Book::frame().
    if (config.display == Display::Double) addStack(out, config, stacks.turned, true);
    addStack(out, config, stacks.unturned, false);
    return out;
}

}  // namespace conecurl
