// Where marks on the fore-edge lie: a leaf's depth in its block, tabs and ticks as world quads, and
// their rectangles on the canvas; see edge_marks.hpp.
#include "edge_marks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec4.hpp>

#include "leaf_placement.hpp"

namespace conecurl {

int leafOfPage(const BookConfig& config, int page) {
    return config.display == Display::Double ? page / 2 : page;
}

bool leafEdge(const Book& book, const Stacks& stacks, int leaf, LeafEdge& out) {
    if (leaf < 0 || leaf >= book.leafCount()) return false;
    const int turnedTop = book.stackTop(true);
    const int unturnedTop = book.stackTop(false);
    const bool turned = leaf <= turnedTop;
    if (!turned && leaf < unturnedTop) return false;  // between the tops: in flight
    if (turned && book.config().display == Display::Single) return false;  // out of view
    const StackDepth& depth = turned ? stacks.turned : stacks.unturned;
    if (!(depth.total() > 0.0)) return false;
    const int fromTop = turned ? turnedTop - leaf : leaf - unturnedTop;
    const int count = turned ? turnedTop + 1 : book.leafCount() - unturnedTop;
    out.turned = turned;
    out.stackDepth = depth.total();
    if (fromTop == 0 && depth.topBoard > 0.0) {
        out.top = 0.0;
        out.bottom = depth.topBoard;
    } else if (fromTop == count - 1 && depth.bottomBoard > 0.0) {
        out.top = depth.topBoard + depth.paper;
        out.bottom = depth.total();
    } else {
        const int paperIndex = fromTop - (depth.topBoard > 0.0 ? 1 : 0);
        out.top = depth.topBoard + paperIndex * depth.leafThickness;
        out.bottom = out.top + depth.leafThickness;
    }
    return true;
}

void tabSlot(const BookConfig& config, int slots, int slot, double& y0, double& y1) {
    const double h = config.pageHeight;
    const double usable = h * (1.0 - 2.0 * kTabEdgeMarginOfHeight);
    const double pitch = std::min(usable / std::max(1, slots), kMaxTabSlotOfHeight * h);
    y1 = h - kTabEdgeMarginOfHeight * h - slot * pitch;
    y0 = y1 - pitch * (1.0 - kTabGapOfSlot);
}

std::vector<EdgeMarkShape> edgeMarkShapes(const Book& book, const std::vector<EdgeMark>& marks) {
    std::vector<EdgeMarkShape> out;
    const BookConfig& c = book.config();
    const Stacks stacks = bookStacks(c, stackLeaves(book), c.leafThickness);
    const LeafPlacement placement = placeLeaf(c.binding, false, c.pageHeight);
    const double w = c.pageWidth;
    const double h = c.pageHeight;
    auto world = [&](bool turned, double x, double y, double d) {
        // A turned leaf lies rotated by pi about the spine: page x runs the other way (book_stacks.cpp).
        const glm::dvec4 p = placement.pageToWorld * glm::dvec4(turned ? -x : x, y, 0.0, 1.0);
        return glm::dvec3(p.x, p.y, -d);
    };
    // Tabs take slots in page order, every tab given counted (shown or not).
    std::vector<int> tabs;
    for (int i = 0; i < static_cast<int>(marks.size()); ++i) {
        if (marks[i].kind == EdgeMarkKind::Tab) tabs.push_back(i);
    }
    std::stable_sort(tabs.begin(), tabs.end(), [&](int a, int b) { return marks[a].page < marks[b].page; });
    const double tickHalf = 0.5 * kTickWidthOfWidth * w;
    for (const EdgeMarkKind kind : {EdgeMarkKind::Tick, EdgeMarkKind::Tab}) {
        for (int i = 0; i < static_cast<int>(marks.size()); ++i) {
            const EdgeMark& mark = marks[i];
            if (mark.kind != kind || mark.page < 0 || mark.page >= c.pageCount) continue;
            // A tab sticks out past the block; a single page fills its box, which has no room for it.
            if (kind == EdgeMarkKind::Tab && c.display == Display::Single) continue;
            LeafEdge edge;
            if (!leafEdge(book, stacks, leafOfPage(c, mark.page), edge)) continue;
            EdgeMarkShape shape;
            shape.mark = i;
            shape.kind = kind;
            shape.turned = edge.turned;
            const double middle = 0.5 * (edge.top + edge.bottom);
            if (kind == EdgeMarkKind::Tick) {
                // On the bevelled face (the outline at depth d is the page grown by d), never above the page.
                const double a = std::max(0.0, middle - tickHalf);
                const double b = std::max(a + 2.0 * tickHalf, middle + tickHalf);
                shape.corners = {world(edge.turned, w + a, -a, a), world(edge.turned, w + a, h + a, a),
                                 world(edge.turned, w + b, h + b, b), world(edge.turned, w + b, -b, b)};
            } else {
                shape.slot = static_cast<int>(std::find(tabs.begin(), tabs.end(), i) - tabs.begin());
                double y0 = 0.0;
                double y1 = 0.0;
                tabSlot(c, static_cast<int>(tabs.size()), shape.slot, y0, y1);
                // Flat at the leaf's depth, from its edge out past the whole block: deeper leaves stick
                // out further (the bevel), so the tab lies on them and under the leaves above it.
                const double inner = w + edge.top;
                const double outer = w + edge.stackDepth + kTabReachOfWidth * w;
                shape.corners = {world(edge.turned, inner, y0, middle), world(edge.turned, outer, y0, middle),
                                 world(edge.turned, outer, y1, middle), world(edge.turned, inner, y1, middle)};
            }
            out.push_back(shape);
        }
    }
    return out;
}

std::vector<EdgeMarkPlace> edgeMarkPlaces(const Book& book, const BookCamera& camera, const std::vector<EdgeMark>& marks) {
    std::vector<EdgeMarkPlace> out;
    for (const EdgeMarkShape& shape : edgeMarkShapes(book, marks)) {
        double x0 = std::numeric_limits<double>::infinity();
        double y0 = x0;
        double x1 = -x0;
        double y1 = -x0;
        for (const glm::dvec3& corner : shape.corners) {
            const glm::dvec2 p = worldToPixel(camera, corner);
            x0 = std::min(x0, p.x);
            y0 = std::min(y0, p.y);
            x1 = std::max(x1, p.x);
            y1 = std::max(y1, p.y);
        }
        EdgeMarkPlace place;
        place.mark = shape.mark;
        place.turned = shape.turned;
        place.kind = shape.kind;
        place.rect = PixelRect{x0, y0, x1 - x0, y1 - y0};
        out.push_back(place);
    }
    return out;
}

}  // namespace conecurl
