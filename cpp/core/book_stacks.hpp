// How thick the stacks of leaves under an open book are, and the faces of their edges (fore-edge,
// head, tail) as triangles: pure math, so the rule is tested natively and the renderer only uploads it.
#pragma once

#include <vector>

#include "book.hpp"

namespace conecurl {

// Leaves lying in each stack: turned (under the left page of a left-bound book) and unturned. The top
// leaf of each stack is the page drawn at the table plane; leaves in flight belong to neither.
struct StackLeaves {
    int turned = 0;
    int unturned = 0;
    bool turnedBottomHard = false;    // the bottom leaf is a board (a hard front cover, turned)
    bool unturnedBottomHard = false;  // a hard back cover
    bool turnedTopHard = false;       // the top leaf is a board
    bool unturnedTopHard = false;
    bool operator==(const StackLeaves& o) const {
        return turned == o.turned && unturned == o.unturned && turnedBottomHard == o.turnedBottomHard &&
               unturnedBottomHard == o.unturnedBottomHard && turnedTopHard == o.turnedTopHard &&
               unturnedTopHard == o.unturnedTopHard;
    }
};

// The leaves of `book` at rest on each side (those in flight, or carried by a riffling leaf, in
// neither), from its stacks' tops: O(turns in flight), not O(leaves).
StackLeaves stackLeaves(const Book& book);

// One stack's depth below the table plane, in world units, in layers from the top: a board on top
// (a hard top leaf), paper, a board at the bottom. Zero depth: no stack.
struct StackDepth {
    double topBoard = 0.0;
    double paper = 0.0;
    double bottomBoard = 0.0;
    double leafThickness = 0.0;  // of one paper leaf as drawn (after the cap): page-edge lines are this apart
    double total() const { return topBoard + paper + bottomBoard; }
};

// Boards are kBoardThicknessOfWidth thick and the paper of a stack never gets deeper than
// kMaxPaperDepthOfWidth (book_constants.hpp, shared with layout.js, which centres a closed book by them).

// `leaves` leaves with paper `leafThicknessOfWidth` (a fraction of `pageWidth` a leaf; 0: no stack).
// A hard leaf at the top or the bottom (a cover) is a board layer of its own; hard leaves in between
// count as paper (hard pages inside a book are rare, and finding them would cost a walk over the leaves).
StackDepth stackDepth(int leaves, bool topHard, bool bottomHard, double leafThicknessOfWidth, double pageWidth);

// The two stacks of a book: depth of each.
struct Stacks {
    StackDepth turned;
    StackDepth unturned;
};
// In single display the page fills its box, and a stack takes what the box has left around it: the
// band the frame margin leaves on every side whatever the box's shape (half the margin's excess of the
// page's smaller side), its layers squeezed in proportion when deeper. It never shrinks the page.
double singleStackRoom(const BookConfig& config);
Stacks bookStacks(const BookConfig& config, const StackLeaves& leaves, double leafThicknessOfWidth);

// Triangles of the stacks' edge faces, 8 floats a vertex: world x y z, s (depth in paper leaves from
// the top of the paper layer; -1 on a board), then the world normal of the face (towards the eye) and
// 0. Each face leaves the page's edge at the table plane and goes down and outward at 45 degrees,
// so that the camera straight above sees it as a band outside the page, as wide as the stack is deep.
// The fore-edge, head and tail of each stack: the spine side is hidden under the binding. In single
// display the turned stack lies outside the view and is left out.
inline constexpr int kStackVertexFloats = 8;
std::vector<float> stackMesh(const BookConfig& config, const Stacks& stacks);

}  // namespace conecurl
