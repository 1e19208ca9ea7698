// Native tests of the marks on the fore-edge (edge_marks.hpp): each leaf's band of depth in its block,
// tabs and ticks at their leaves, moving from one block to the other as leaves turn, and their
// rectangles on the canvas beside the open pages.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "book.hpp"
#include "book_camera.hpp"
#include "book_stacks.hpp"
#include "edge_marks.hpp"
#include "leaf_placement.hpp"

namespace {

using namespace conecurl;

Book makeBook(int pages, Display display = Display::Double, std::vector<bool> hard = {}) {
    BookConfig config;
    config.pageCount = pages;
    config.display = display;
    config.hardPages = std::move(hard);
    return Book(config);
}

Stacks stacksOf(const Book& book) {
    return bookStacks(book.config(), stackLeaves(book), book.config().leafThickness);
}

TEST(EdgeMarks, PagesBelongToTheLeafThatHoldsThem) {
    const Book twoPages = makeBook(10);
    EXPECT_EQ(leafOfPage(twoPages.config(), 0), 0);
    EXPECT_EQ(leafOfPage(twoPages.config(), 1), 0);
    EXPECT_EQ(leafOfPage(twoPages.config(), 7), 3);
    const Book onePage = makeBook(10, Display::Single);
    EXPECT_EQ(leafOfPage(onePage.config(), 7), 7);
}

TEST(EdgeMarks, LeafBandsTileEachBlockFromTheOpenPageDown) {
    Book book = makeBook(120);
    book.jumpTo(20);
    const Stacks stacks = stacksOf(book);
    // Unturned block: leaves 20..59, the open leaf on top.
    double expectTop = 0.0;
    for (int leaf = 20; leaf < 60; ++leaf) {
        LeafEdge edge;
        ASSERT_TRUE(leafEdge(book, stacks, leaf, edge)) << leaf;
        EXPECT_FALSE(edge.turned);
        EXPECT_NEAR(edge.top, expectTop, 1e-12) << leaf;
        EXPECT_GT(edge.bottom, edge.top);
        expectTop = edge.bottom;
    }
    EXPECT_NEAR(expectTop, stacks.unturned.total(), 1e-12);
    // Turned block: leaves 19 down to 0, the open leaf (19) on top.
    expectTop = 0.0;
    for (int leaf = 19; leaf >= 0; --leaf) {
        LeafEdge edge;
        ASSERT_TRUE(leafEdge(book, stacks, leaf, edge)) << leaf;
        EXPECT_TRUE(edge.turned);
        EXPECT_NEAR(edge.top, expectTop, 1e-12) << leaf;
        expectTop = edge.bottom;
    }
    EXPECT_NEAR(expectTop, stacks.turned.total(), 1e-12);
    LeafEdge none;
    EXPECT_FALSE(leafEdge(book, stacks, 60, none));
    EXPECT_FALSE(leafEdge(book, stacks, -1, none));
}

TEST(EdgeMarks, HardCoversAreTheBoardsOfTheirBlock) {
    std::vector<bool> hard(40, false);
    hard[0] = hard[1] = hard[38] = hard[39] = true;
    Book book = makeBook(40, Display::Double, hard);
    book.jumpTo(1);  // the front cover turned alone, the back cover at the bottom of the unturned block
    const Stacks stacks = stacksOf(book);
    LeafEdge front;
    ASSERT_TRUE(leafEdge(book, stacks, 0, front));
    EXPECT_TRUE(front.turned);
    EXPECT_EQ(front.top, 0.0);
    EXPECT_NEAR(front.bottom, kBoardThicknessOfWidth * book.config().pageWidth, 1e-15);
    LeafEdge back;
    ASSERT_TRUE(leafEdge(book, stacks, 19, back));
    EXPECT_NEAR(back.bottom, stacks.unturned.total(), 1e-15);
    EXPECT_NEAR(back.bottom - back.top, kBoardThicknessOfWidth * book.config().pageWidth, 1e-15);
    LeafEdge first;
    ASSERT_TRUE(leafEdge(book, stacks, 1, first));
    EXPECT_EQ(first.top, 0.0);  // the open page's leaf, paper
}

TEST(EdgeMarks, MarksMoveToTheOtherBlockAsTheirLeafTurnsAndHideInFlight) {
    Book book = makeBook(60);
    book.jumpTo(5);
    const std::vector<EdgeMark> marks{{10, EdgeMarkKind::Tab}};  // page 10: leaf 5, the open right page
    auto shapes = edgeMarkShapes(book, marks);
    ASSERT_EQ(shapes.size(), 1u);
    EXPECT_FALSE(shapes[0].turned);
    ASSERT_TRUE(book.startTurn(TurnDirection::Forward));
    book.setLatestTurnProgress(0.5);
    EXPECT_TRUE(edgeMarkShapes(book, marks).empty()) << "leaf 5 is in flight";
    book.advance(10.0);
    shapes = edgeMarkShapes(book, marks);
    ASSERT_EQ(shapes.size(), 1u);
    EXPECT_TRUE(shapes[0].turned);
}

TEST(EdgeMarks, SingleDisplayShowsOnlyTheUnturnedBlock) {
    Book book = makeBook(30, Display::Single);
    book.jumpTo(10);
    const std::vector<EdgeMark> marks{{3, EdgeMarkKind::Tab}, {20, EdgeMarkKind::Tick}};
    const auto shapes = edgeMarkShapes(book, marks);
    ASSERT_EQ(shapes.size(), 1u);
    EXPECT_EQ(shapes[0].mark, 1);
    EXPECT_EQ(shapes[0].kind, EdgeMarkKind::Tick);
}

TEST(EdgeMarks, SingleDisplayFoldsTheTabsAwayAndKeepsTheTicks) {
    Book book = makeBook(30, Display::Single);
    book.jumpTo(10);
    const std::vector<EdgeMark> marks{{20, EdgeMarkKind::Tab}, {25, EdgeMarkKind::Tick}};
    const auto shapes = edgeMarkShapes(book, marks);
    ASSERT_EQ(shapes.size(), 1u);
    EXPECT_EQ(shapes[0].kind, EdgeMarkKind::Tick);
    // The tick lies within the squeezed block, in the band around the page (book_stacks.hpp).
    for (const glm::dvec3& corner : shapes[0].corners) EXPECT_GE(corner.z, -singleStackRoom(book.config()) - 1e-9);
}

TEST(EdgeMarks, NoThicknessNoMarks) {
    BookConfig config;
    config.pageCount = 20;
    config.leafThickness = 0.0;
    const Book book(config);
    EXPECT_TRUE(edgeMarkShapes(book, {{4, EdgeMarkKind::Tab}, {6, EdgeMarkKind::Tick}}).empty());
}

// Page x (from the spine, outward) and page y of a world point on the unturned side of a left-bound book.
glm::dvec2 pagePointOf(const Book& book, glm::dvec3 world, bool turned) {
    const LeafPlacement placement = placeLeaf(book.config().binding, false, book.config().pageHeight);
    const glm::dvec4 p = glm::inverse(placement.pageToWorld) * glm::dvec4(world.x, world.y, 0.0, 1.0);
    return {turned ? -p.x : p.x, p.y};
}

TEST(EdgeMarks, TabsLieFlatAtTheirLeafFromItsEdgeOutPastTheBlockInSlotsByPage) {
    Book book = makeBook(200);
    book.jumpTo(30);
    const Stacks stacks = stacksOf(book);
    const double w = book.config().pageWidth;
    const double h = book.config().pageHeight;
    // Given out of order: slots follow the pages.
    const std::vector<EdgeMark> marks{{150, EdgeMarkKind::Tab}, {2, EdgeMarkKind::Tab}, {90, EdgeMarkKind::Tab}};
    const auto shapes = edgeMarkShapes(book, marks);
    ASSERT_EQ(shapes.size(), 3u);
    double previousLow = h + 1.0;
    for (const int mark : {1, 2, 0}) {
        const auto it = std::find_if(shapes.begin(), shapes.end(), [&](const EdgeMarkShape& s) { return s.mark == mark; });
        ASSERT_NE(it, shapes.end());
        LeafEdge edge;
        ASSERT_TRUE(leafEdge(book, stacks, leafOfPage(book.config(), marks[mark].page), edge));
        EXPECT_EQ(it->turned, edge.turned);
        double xMin = 1e9, xMax = -1e9, yMin = 1e9, yMax = -1e9;
        for (const glm::dvec3& corner : it->corners) {
            EXPECT_NEAR(corner.z, -0.5 * (edge.top + edge.bottom), 1e-12);  // flat at its leaf
            const glm::dvec2 p = pagePointOf(book, corner, edge.turned);
            xMin = std::min(xMin, p.x);
            xMax = std::max(xMax, p.x);
            yMin = std::min(yMin, p.y);
            yMax = std::max(yMax, p.y);
        }
        EXPECT_NEAR(xMin, w + edge.top, 1e-9);  // starts where its leaf's edge shows on the bevel
        EXPECT_NEAR(xMax, w + edge.stackDepth + kTabReachOfWidth * w, 1e-9);  // out past the block
        EXPECT_LT(yMax, previousLow) << "slots go down the edge in page order, apart";
        EXPECT_GT(yMin, 0.0);
        EXPECT_LT(yMax, h);
        previousLow = yMin;
    }
    // The first section's tab is on the turned block, the later ones on the unturned block.
    EXPECT_TRUE(std::find_if(shapes.begin(), shapes.end(), [](const EdgeMarkShape& s) { return s.mark == 1; })->turned);
    EXPECT_FALSE(std::find_if(shapes.begin(), shapes.end(), [](const EdgeMarkShape& s) { return s.mark == 0; })->turned);
}

TEST(EdgeMarks, TicksLieOnTheBevelledFaceAroundTheirLeafHeadToTail) {
    Book book = makeBook(400);
    book.jumpTo(50);
    const Stacks stacks = stacksOf(book);
    const double w = book.config().pageWidth;
    const double h = book.config().pageHeight;
    for (const int page : {40, 300}) {
        const auto shapes = edgeMarkShapes(book, {{page, EdgeMarkKind::Tick}});
        ASSERT_EQ(shapes.size(), 1u);
        LeafEdge edge;
        ASSERT_TRUE(leafEdge(book, stacks, leafOfPage(book.config(), page), edge));
        const double middle = 0.5 * (edge.top + edge.bottom);
        double dMin = 1e9, dMax = -1e9;
        for (const glm::dvec3& corner : shapes[0].corners) {
            const double d = -corner.z;
            const glm::dvec2 p = pagePointOf(book, corner, edge.turned);
            EXPECT_NEAR(p.x, w + d, 1e-9) << "on the 45 degree face";
            EXPECT_TRUE(std::abs(p.y + d) < 1e-9 || std::abs(p.y - h - d) < 1e-9) << "tail to head";
            dMin = std::min(dMin, d);
            dMax = std::max(dMax, d);
        }
        EXPECT_NEAR(0.5 * (dMin + dMax), middle, 1e-12);
        EXPECT_NEAR(dMax - dMin, kTickWidthOfWidth * w, 1e-12);  // wider than a leaf: it shows
        EXPECT_GT(dMax - dMin, edge.bottom - edge.top);
    }
}

TEST(EdgeMarks, PlacesOnTheCanvasLieOutsideTheOpenPagesOnTheirSide) {
    Book book = makeBook(300);
    book.jumpTo(60);
    const BookCamera camera = bookCamera(book, 1200, 800, true);
    const OpenPages open = openPagePlaces(book, camera);
    ASSERT_EQ(open.count, 2);
    const PixelRect left = open.places[0].rect;
    const PixelRect right = open.places[1].rect;
    const std::vector<EdgeMark> marks{{10, EdgeMarkKind::Tab}, {280, EdgeMarkKind::Tab}, {200, EdgeMarkKind::Tab}};
    const auto places = edgeMarkPlaces(book, camera, marks);
    ASSERT_EQ(places.size(), 3u);
    for (const EdgeMarkPlace& place : places) {
        EXPECT_GT(place.rect.width, 4.0);
        EXPECT_GT(place.rect.height, 4.0);
        if (place.turned) {
            EXPECT_LE(place.rect.x + place.rect.width, left.x + 1e-6);
        } else {
            EXPECT_GE(place.rect.x, right.x + right.width - 1e-6);
        }
        EXPECT_GE(place.rect.y, std::min(left.y, right.y));
        EXPECT_LE(place.rect.y + place.rect.height, std::max(left.y + left.height, right.y + right.height));
    }
    auto placeOf = [&](int mark) {
        return *std::find_if(places.begin(), places.end(), [&](const EdgeMarkPlace& p) { return p.mark == mark; });
    };
    EXPECT_TRUE(placeOf(0).turned);
    EXPECT_FALSE(placeOf(1).turned);
    // Deeper in the block, further out: page 280's leaf lies below page 200's.
    EXPECT_GT(placeOf(1).rect.x, placeOf(2).rect.x);
}

}  // namespace
