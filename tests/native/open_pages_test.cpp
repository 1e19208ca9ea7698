// Native tests of openPagePlaces: the pages lying open tile the resting rectangle on the side the engine
// lays them (so the 2D fallback, which copies the answer, draws each page where the WebGL book does).
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "book.hpp"
#include "book_camera.hpp"

namespace {

using conecurl::Binding;
using conecurl::Book;
using conecurl::BookCamera;
using conecurl::BookConfig;
using conecurl::Display;
using conecurl::kNoPage;
using conecurl::OpenPages;
using conecurl::PixelRect;
using conecurl::TurnDirection;
using conecurl::ViewZoom;

Book makeBook(int pageCount, Display display, Binding binding) {
    BookConfig config;
    config.pageCount = pageCount;
    config.display = display;
    config.binding = binding;
    config.pageWidth = 0.7;  // neither the default nor the height: a swapped one shows
    config.pageHeight = 1.1;
    return Book(config);
}

void expectRect(const PixelRect& actual, const PixelRect& expected, const std::string& where) {
    constexpr double kTolerance = 1e-9 * 800;
    EXPECT_NEAR(actual.x, expected.x, kTolerance) << where;
    EXPECT_NEAR(actual.y, expected.y, kTolerance) << where;
    EXPECT_NEAR(actual.width, expected.width, kTolerance) << where;
    EXPECT_NEAR(actual.height, expected.height, kTolerance) << where;
}

std::vector<int> pagesOf(const OpenPages& open) {
    std::vector<int> pages;
    for (int i = 0; i < open.count; ++i) pages.push_back(open.places[i].page);
    return pages;
}

std::string nameOf(Binding binding) {
    return binding == Binding::Left ? "left" : binding == Binding::Right ? "right" : "top";
}

TEST(OpenPagePlaces, TileTheRestingRectTurnedSideFirstForEveryBindingDisplayAndZoom) {
    int checked = 0;
    for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
        for (Display display : {Display::Single, Display::Double}) {
            for (int pageCount : {7, 8}) {
                Book book = makeBook(pageCount, display, binding);
                for (int position = 0; position <= book.lastPosition(); ++position) {
                    book.jumpTo(position);
                    for (const ViewZoom& zoom : {ViewZoom{}, ViewZoom{2.0, 0.3, -0.5}}) {
                        for (auto [width, height] : {std::pair{800, 600}, std::pair{300, 700}}) {
                            const BookCamera camera = conecurl::bookCamera(book.config(), width, height, zoom);
                            const PixelRect all = conecurl::restingRect(camera, book.config());
                            const OpenPages open = conecurl::openPagePlaces(book, camera);
                            const std::string where = nameOf(binding) + (display == Display::Single ? " single " : " double ") +
                                                      std::to_string(pageCount) + " pages, position " + std::to_string(position) +
                                                      ", zoom " + std::to_string(zoom.scale) + ", " + std::to_string(width) + "x" +
                                                      std::to_string(height);
                            if (display == Display::Single) {
                                ASSERT_EQ(open.count, 1) << where;
                                expectRect(open.places[0].rect, all, where);
                                EXPECT_FALSE(open.places[0].turned) << where;
                            } else {
                                // Halves left and right (top and bottom for Top); the turned side is the
                                // left (Left), right (Right) or top (Top) one.
                                PixelRect first = all;
                                PixelRect second = all;
                                if (binding == Binding::Top) {
                                    first.height = second.height = all.height / 2;
                                    second.y = all.y + all.height / 2;
                                } else {
                                    first.width = second.width = all.width / 2;
                                    second.x = all.x + all.width / 2;
                                }
                                const PixelRect& turned = binding == Binding::Right ? second : first;
                                const PixelRect& unturned = binding == Binding::Right ? first : second;
                                const bool hasTurned = position > 0;
                                const bool hasUnturned = position < book.leafCount();
                                ASSERT_EQ(open.count, int(hasTurned) + int(hasUnturned)) << where;
                                if (hasTurned) expectRect(open.places[0].rect, turned, where + ", turned");
                                if (hasUnturned) expectRect(open.places[open.count - 1].rect, unturned, where + ", unturned");
                                EXPECT_EQ(open.places[0].turned, hasTurned) << where;
                                if (open.count == 2) EXPECT_FALSE(open.places[1].turned) << where;
                            }
                            ++checked;
                        }
                    }
                }
            }
        }
    }
    // Positions of a 7- and an 8-page book: single 7 + 8, double 5 + 5; each 3 bindings, 2 zooms, 2 sizes.
    EXPECT_EQ(checked, (7 + 8 + 5 + 5) * 3 * 2 * 2);
}

TEST(OpenPagePlaces, ShowTheTurnedLeafsBackAndTheUnturnedLeafsFrontAtTheFirstMiddleAndLastPositions) {
    struct Case {
        Display display;
        int pageCount;
        int position;
        std::vector<int> pages;
    };
    const std::vector<Case> cases = {
        {Display::Double, 7, 0, {0}},
        {Display::Double, 7, 2, {3, 4}},
        {Display::Double, 7, 4, {kNoPage}},  // the last leaf's blank back
        {Display::Double, 8, 0, {0}},
        {Display::Double, 8, 2, {3, 4}},
        {Display::Double, 8, 4, {7}},
        {Display::Single, 7, 0, {0}},
        {Display::Single, 7, 3, {3}},
        {Display::Single, 7, 6, {6}},
        {Display::Single, 8, 0, {0}},
        {Display::Single, 8, 4, {4}},
        {Display::Single, 8, 7, {7}},
    };
    for (const Case& c : cases) {
        for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
            Book book = makeBook(c.pageCount, c.display, binding);
            book.jumpTo(c.position);
            ASSERT_EQ(book.position(), c.position);
            EXPECT_EQ(pagesOf(conecurl::openPagePlaces(book, conecurl::bookCamera(book.config(), 640, 480))), c.pages)
                << nameOf(binding) << ", " << c.pageCount << " pages, position " << c.position;
        }
    }
}

TEST(OpenPagePlaces, WithTurnsInFlightAreWhereTheTurnsLand) {
    for (Display display : {Display::Single, Display::Double}) {
        Book turning = makeBook(9, display, Binding::Left);
        turning.jumpTo(2);
        ASSERT_TRUE(turning.startTurn(TurnDirection::Forward));
        ASSERT_TRUE(turning.startTurn(TurnDirection::Forward));
        turning.setLatestTurnProgress(0.4);
        Book landed = makeBook(9, display, Binding::Left);
        landed.jumpTo(4);
        const OpenPages a = conecurl::openPagePlaces(turning, conecurl::bookCamera(turning.config(), 640, 480));
        const OpenPages b = conecurl::openPagePlaces(landed, conecurl::bookCamera(landed.config(), 640, 480));
        ASSERT_EQ(pagesOf(a), pagesOf(b));
        for (int i = 0; i < a.count; ++i) expectRect(a.places[i].rect, b.places[i].rect, "place " + std::to_string(i));
    }
}

TEST(OpenPagePlaces, ABookWithoutPagesHasNone) {
    for (Display display : {Display::Single, Display::Double}) {
        const Book book = makeBook(0, display, Binding::Left);
        EXPECT_EQ(conecurl::openPagePlaces(book, conecurl::bookCamera(book.config(), 640, 480)).count, 0);
    }
}

}  // namespace
