// Native tests of the stacks' depth rule and edge faces: depth follows the leaves on each side, is
// capped smoothly, counts boards once, and the faces lie outside the pages, below the table, facing up.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "book.hpp"
#include "book_stacks.hpp"

namespace {

using namespace conecurl;

constexpr double kLeaf = 0.004;  // a leaf's thickness, of the page width

Book makeBook(int pages, Display display = Display::Double, Binding binding = Binding::Left,
              std::vector<bool> hard = {}) {
    BookConfig config;
    config.pageCount = pages;
    config.display = display;
    config.binding = binding;
    config.hardPages = std::move(hard);
    return Book(config);
}

TEST(BookStacks, NoLeavesOrNoThicknessGivesNoDepth) {
    EXPECT_EQ(stackDepth(0, false, false, kLeaf, 0.8).total(), 0.0);
    EXPECT_EQ(stackDepth(10, true, true, 0.0, 0.8).total(), 0.0);
    EXPECT_EQ(stackDepth(-3, false, false, kLeaf, 0.8).total(), 0.0);
}

TEST(BookStacks, DepthIsAboutLeavesTimesThicknessForAThinStack) {
    const StackDepth d = stackDepth(3, false, false, kLeaf, 0.8);
    const double raw = 3 * kLeaf * 0.8;
    EXPECT_NEAR(d.paper, raw, 0.03 * raw);
    EXPECT_LT(d.paper, raw);  // the cap already bends it, a little
    EXPECT_NEAR(d.leafThickness * 3, d.paper, 1e-15);
}

TEST(BookStacks, EveryLeafAddsDepthAndAThousandLeavesStayUnderTheCap) {
    double previous = 0.0;
    for (int leaves = 1; leaves <= 1000; ++leaves) {
        const double depth = stackDepth(leaves, false, false, kLeaf, 0.8).total();
        ASSERT_GT(depth, previous) << leaves << " leaves";
        previous = depth;
    }
    EXPECT_LT(previous, kMaxPaperDepthOfWidth * 0.8);
    EXPECT_GT(previous, 0.99 * kMaxPaperDepthOfWidth * 0.8);
}

TEST(BookStacks, HardCoversAreBoardLayersCountedOnce) {
    const double board = kBoardThicknessOfWidth * 0.8;
    const StackDepth both = stackDepth(10, true, true, kLeaf, 0.8);
    EXPECT_EQ(both.topBoard, board);
    EXPECT_EQ(both.bottomBoard, board);
    EXPECT_NEAR(both.paper, stackDepth(8, false, false, kLeaf, 0.8).paper, 1e-15);  // 8 paper leaves between
    const StackDepth cover = stackDepth(1, true, true, kLeaf, 0.8);  // the cover alone: top and bottom at once
    EXPECT_EQ(cover.total(), board);
    const StackDepth back = stackDepth(1, false, true, kLeaf, 0.8);
    EXPECT_EQ(back.total(), board);
    EXPECT_EQ(back.paper, 0.0);
}

TEST(BookStacks, LeavesOnEachSideFollowThePositionAndLeaveOutLeavesInFlight) {
    Book book = makeBook(20);  // 10 leaves
    EXPECT_EQ(book.leafCount(), 10);
    for (int p = 0; p <= 10; ++p) {
        book.jumpTo(p);
        const StackLeaves s = stackLeaves(book);
        EXPECT_EQ(s.turned, p);
        EXPECT_EQ(s.unturned, 10 - p);
    }
    book.jumpTo(4);
    ASSERT_TRUE(book.startTurn(TurnDirection::Forward));
    ASSERT_TRUE(book.startTurn(TurnDirection::Forward));
    StackLeaves s = stackLeaves(book);
    EXPECT_EQ(s.turned, 4);    // leaves 4 and 5 are in the air: in neither stack
    EXPECT_EQ(s.unturned, 4);
    book.jumpTo(4);
    ASSERT_TRUE(book.startTurn(TurnDirection::Backward));
    s = stackLeaves(book);
    EXPECT_EQ(s.turned, 3);
    EXPECT_EQ(s.unturned, 6);
}

TEST(BookStacks, OverTenTurnsTheTurnedStackDeepensAndTheUnturnedThins) {
    Book book = makeBook(40);
    double turned = -1.0;
    double unturned = 1e9;
    for (int turn = 0; turn < 10; ++turn) {
        ASSERT_TRUE(book.startTurn(TurnDirection::Forward));
        book.advance(10.0);  // lands
        const Stacks s = bookStacks(book.config(), stackLeaves(book), kLeaf);
        EXPECT_GT(s.turned.total(), turned) << "turn " << turn;
        EXPECT_LT(s.unturned.total(), unturned) << "turn " << turn;
        turned = s.turned.total();
        unturned = s.unturned.total();
    }
}

TEST(BookStacks, HardCoversOfAClosedAndAnOpenBook) {
    // Pages 0, 1 and 18, 19 are boards: leaves 0 and 9.
    std::vector<bool> hard(20, false);
    hard[0] = hard[1] = hard[18] = hard[19] = true;
    Book book = makeBook(20, Display::Double, Binding::Left, hard);
    StackLeaves s = stackLeaves(book);
    EXPECT_TRUE(s.unturnedTopHard);
    EXPECT_TRUE(s.unturnedBottomHard);
    EXPECT_FALSE(s.turnedTopHard || s.turnedBottomHard);
    book.jumpTo(3);
    s = stackLeaves(book);
    EXPECT_FALSE(s.turnedTopHard);
    EXPECT_TRUE(s.turnedBottomHard);  // the front cover, under the turned leaves
    EXPECT_FALSE(s.unturnedTopHard);
    EXPECT_TRUE(s.unturnedBottomHard);
}

struct Vertex {
    double x, y, z, s, nx, ny, nz;
};

std::vector<Vertex> vertices(const std::vector<float>& mesh) {
    std::vector<Vertex> out;
    for (size_t i = 0; i + kStackVertexFloats <= mesh.size(); i += kStackVertexFloats) {
        out.push_back({mesh[i], mesh[i + 1], mesh[i + 2], mesh[i + 3], mesh[i + 4], mesh[i + 5], mesh[i + 6]});
    }
    return out;
}

TEST(BookStacks, FacesLieOutsideThePagesBelowTheTableFacingUpAndOut) {
    Book book = makeBook(20);
    book.jumpTo(3);
    const BookConfig& c = book.config();
    const Stacks stacks = bookStacks(c, stackLeaves(book), kLeaf);
    const std::vector<Vertex> mesh = vertices(stackMesh(c, stacks));
    ASSERT_EQ(mesh.size(), 2u * 3u * 6u);  // two stacks, three faces, one paper layer each
    const double deepest = std::max(stacks.turned.total(), stacks.unturned.total());
    for (const Vertex& v : mesh) {
        EXPECT_LE(v.z, 0.0);
        EXPECT_GE(v.z, -deepest - 1e-7);
        EXPECT_GT(v.nz, 0.5);  // 45 degrees: nz = 1/sqrt 2
        // Outside the spread (|x| < w, |y| < h/2) or on its edge; the outward part of the normal points out.
        const bool inside = std::abs(v.x) < c.pageWidth - 1e-6 && std::abs(v.y) < 0.5 * c.pageHeight - 1e-6;
        EXPECT_FALSE(inside) << v.x << ", " << v.y;
        // Every vertex is as far out as it is deep (the bevel): beyond the page by -z on x or on y.
        const double beyond = std::max(std::abs(v.x) - c.pageWidth, std::abs(v.y) - 0.5 * c.pageHeight);
        EXPECT_NEAR(beyond, -v.z, 1e-6) << v.x << ", " << v.y << ", " << v.z;
    }
    // The turned stack is the one on the left: its fore-edge reaches out as far as it is deep.
    double left = 0.0;
    double right = 0.0;
    for (const Vertex& v : mesh) {
        left = std::min(left, v.x);
        right = std::max(right, v.x);
    }
    EXPECT_NEAR(-left - c.pageWidth, stacks.turned.total(), 1e-6);
    EXPECT_NEAR(right - c.pageWidth, stacks.unturned.total(), 1e-6);
}

TEST(BookStacks, RightToLeftPutsTheTurnedStackOnTheRightAndSingleDisplayLeavesItOut) {
    Book rtl = makeBook(20, Display::Double, Binding::Right);
    rtl.jumpTo(8);  // 8 leaves turned, 2 unturned: the turned stack is the deeper one
    const Stacks s = bookStacks(rtl.config(), stackLeaves(rtl), kLeaf);
    double right = 0.0;
    for (const Vertex& v : vertices(stackMesh(rtl.config(), s))) right = std::max(right, v.x);
    EXPECT_NEAR(right - rtl.config().pageWidth, s.turned.total(), 1e-6);

    Book single = makeBook(20, Display::Single);
    single.jumpTo(8);
    const Stacks t = bookStacks(single.config(), stackLeaves(single), kLeaf);
    const std::vector<Vertex> mesh = vertices(stackMesh(single.config(), t));
    EXPECT_EQ(mesh.size(), 3u * 6u);
    for (const Vertex& v : mesh) EXPECT_GE(v.x, 0.0);
}

TEST(BookStacks, SingleDisplaySqueezesAStackIntoTheBandTheFrameMarginLeaves) {
    std::vector<bool> hard(400, false);
    hard[0] = hard[399] = true;
    Book single = makeBook(400, Display::Single, Binding::Left, hard);
    single.jumpTo(10);
    const double room = singleStackRoom(single.config());
    EXPECT_NEAR(room, 0.5 * (kSingleFrameMargin - 1.0) * std::min(single.config().pageWidth, single.config().pageHeight), 1e-12);
    const Stacks deep = bookStacks(single.config(), stackLeaves(single), kLeaf);
    EXPECT_NEAR(deep.unturned.total(), room, 1e-12);
    // Squeezed in proportion: a board stays a board, the page-edge lines stay one a leaf.
    const StackLeaves leaves = stackLeaves(single);  // 390 leaves unturned, the last a board
    const StackDepth natural = stackDepth(leaves.unturned, leaves.unturnedTopHard, leaves.unturnedBottomHard, kLeaf,
                                          single.config().pageWidth);
    ASSERT_GT(natural.bottomBoard, 0.0);
    const double k = room / natural.total();
    EXPECT_NEAR(deep.unturned.bottomBoard, natural.bottomBoard * k, 1e-12);
    EXPECT_NEAR(deep.unturned.leafThickness, natural.leafThickness * k, 1e-12);
    double far = 0.0;
    for (const Vertex& v : vertices(stackMesh(single.config(), deep))) far = std::max(far, v.x - single.config().pageWidth);
    EXPECT_LE(far, room + 1e-6);
    // A thin stack that fits keeps its depth.
    single.jumpTo(398);
    const Stacks thin = bookStacks(single.config(), stackLeaves(single), kLeaf);
    EXPECT_NEAR(thin.unturned.total(), stackDepth(2, false, true, kLeaf, single.config().pageWidth).total(), 1e-12);
}

TEST(BookStacks, PageEdgeLinesCountTheLeavesAndBoardsAreMarked) {
    std::vector<bool> hard(20, false);
    hard[18] = hard[19] = true;
    Book book = makeBook(20, Display::Double, Binding::Left, hard);
    book.jumpTo(2);  // unturned: leaves 2..9, the last a board
    const Stacks s = bookStacks(book.config(), stackLeaves(book), kLeaf);
    double maxS = 0.0;
    int board = 0;
    for (const Vertex& v : vertices(stackMesh(book.config(), s))) {
        maxS = std::max(maxS, v.s);
        board += v.s == -1.0;
    }
    EXPECT_NEAR(maxS, 7.0, 1e-5);  // 7 paper leaves over the back board in the unturned stack
    EXPECT_EQ(board, 3 * 6);       // the back board's three faces
}

}  // namespace
