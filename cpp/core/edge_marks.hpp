// Marks on the book's fore-edge: index tabs for the outline's sections and ticks for search hits, each
// at the depth of its leaf in the page block it lies in. Pure math (world geometry and its place on the
// canvas), so the rule is tested natively; the renderer only uploads and draws it.
#pragma once

#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "book.hpp"
#include "book_camera.hpp"
#include "book_stacks.hpp"

namespace conecurl {

enum class EdgeMarkKind { Tab = 0, Tick = 1 };

// A mark as the page it belongs to: the leaf holding that page carries it.
struct EdgeMark {
    int page = 0;
    EdgeMarkKind kind = EdgeMarkKind::Tab;
};

// A tab sticks out past the block's outer edge by this fraction of the page width.
inline constexpr double kTabReachOfWidth = 0.08;
// Tabs share the fore-edge from the head down, each in its own slot, at most this tall (of the page
// height), with this much of a slot left as a gap between neighbours.
inline constexpr double kMaxTabSlotOfHeight = 0.13;
inline constexpr double kTabGapOfSlot = 0.18;
inline constexpr double kTabEdgeMarginOfHeight = 0.05;  // the first slot starts this far below the head
// A tick is this wide (of the page width, across the block's depth), however thin a leaf is, so a hit
// on one leaf of a 1000-page book still shows.
inline constexpr double kTickWidthOfWidth = 0.006;

// The leaf that holds `page` (double display: a leaf per two pages, front and back; single: one).
int leafOfPage(const BookConfig& config, int page);

// Where a leaf's edge lies in the block: the stack (turned or not) and its band of depth below the
// table plane, in world units, from `top` down to `bottom` (0 for the leaf lying open on top).
struct LeafEdge {
    bool turned = false;
    double top = 0.0;
    double bottom = 0.0;
    double stackDepth = 0.0;  // the whole block's depth on that side
};
// false when the leaf lies in neither drawn block: in flight (or carried by a riffle), on the turned
// side in single display (out of view), out of the book, or with no thickness.
bool leafEdge(const Book& book, const Stacks& stacks, int leaf, LeafEdge& out);

// One mark's shape in the world: a quad (corners in order, either winding) and the mark it draws.
// A tab is flat at its leaf's depth, from the leaf's edge out past the block, in its slot along the
// edge; a tick is a band on the bevelled fore-edge face around its leaf's depth, head to tail.
struct EdgeMarkShape {
    int mark = 0;   // index into the marks given
    int slot = 0;   // a tab's slot from the head (its order among the tabs, by page); 0 for a tick
    bool turned = false;
    EdgeMarkKind kind = EdgeMarkKind::Tab;
    std::array<glm::dvec3, 4> corners{};
};
// Shapes of the marks that show now, ticks first (tabs lie over them). Tabs are ordered by page for
// their slots (ties by their order given); marks on leaves not shown are left out, and so are tabs in
// single display (the page fills its box: no room past the block's edge for a tab to stick out).
std::vector<EdgeMarkShape> edgeMarkShapes(const Book& book, const std::vector<EdgeMark>& marks);

// The tabs' slots along the edge: how many there are (all tabs given, shown or not, so a tab keeps
// its slot as leaves turn) and where slot `i` lies, as page y from `y0` (lower) to `y1` (upper).
void tabSlot(const BookConfig& config, int slots, int slot, double& y0, double& y1);

// Each shape's rectangle on the canvas under `camera` (its corners' bounding box), in pixels.
struct EdgeMarkPlace {
    int mark = 0;
    bool turned = false;
    EdgeMarkKind kind = EdgeMarkKind::Tab;
    PixelRect rect;
};
std::vector<EdgeMarkPlace> edgeMarkPlaces(const Book& book, const BookCamera& camera, const std::vector<EdgeMark>& marks);

}  // namespace conecurl
