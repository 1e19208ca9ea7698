// Native (GoogleTest via CTest) tests of dragging: the camera's projections, which leaf a press takes
// hold of, the pose solve that keeps the grabbed point under the pointer, release, and held turns.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "book.hpp"
#include "book_camera.hpp"
#include "cone_deform.hpp"
#include "leaf_placement.hpp"
#include "page_drag.hpp"

namespace {

using namespace conecurl;
using glm::dvec2;
using glm::dvec3;
using glm::dvec4;

constexpr double kPi = 3.14159265358979323846;
constexpr double kW = 0.7;
constexpr double kH = 1.1;
constexpr int kCanvasW = 900;
constexpr int kCanvasH = 600;

Book makeBook(Binding binding, Display display, int pageCount = 10, std::vector<bool> hard = {}) {
    BookConfig config;
    config.pageCount = pageCount;
    config.display = display;
    config.binding = binding;
    config.pageWidth = kW;
    config.pageHeight = kH;
    config.hardPages = std::move(hard);
    return Book(config);
}

const char* name(Binding b) { return b == Binding::Left ? "left" : b == Binding::Right ? "right" : "top"; }

// Pixel of a page point of a leaf resting unturned (mirrored: resting turned), from the placement
// tables directly: independent of how page_drag finds its way back.
dvec2 restingPixel(const Book& book, const BookCamera& camera, bool turned, dvec2 leafPoint) {
    const LeafPlacement p = placeLeaf(book.config().binding, turned, kH);
    return worldToPixel(camera, dvec3(p.pageToWorld * dvec4(leafPoint, 0.0, 1.0)));
}

// Pixel of the grabbed point as the renderer draws the held leaf: LeafDraw -> leafPointToWorld.
dvec2 drawnGripPixel(const Book& book, const BookCamera& camera, const Grip& grip) {
    const BookFrame frame = book.frame();
    for (int i = 0; i < frame.count; ++i) {
        if (frame.leaves[i].leaf == book.heldLeaf() && !frame.leaves[i].resting) {
            return worldToPixel(camera, leafPointToWorld(frame.leaves[i], book.config().binding, kH, grip.pagePoint));
        }
    }
    ADD_FAILURE() << "the held leaf is not in the frame";
    return {0.0, 0.0};
}

TEST(BookCameraNative, PixelToTableAndBackRoundTripsAndThePagesFitTheCanvas) {
    for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
        for (Display display : {Display::Single, Display::Double}) {
            const Book book = makeBook(binding, display);
            const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
            for (double x : {0.0, 123.4, 450.0, 899.0}) {
                for (double y : {0.0, 300.0, 599.5}) {
                    const dvec3 table = pixelToTable(camera, {x, y});
                    EXPECT_NEAR(table.z, 0.0, 1e-9);
                    const dvec2 back = worldToPixel(camera, table);
                    EXPECT_NEAR(back.x, x, 1e-6) << name(binding);
                    EXPECT_NEAR(back.y, y, 1e-6) << name(binding);
                }
            }
            // Every corner of the unturned page is on the canvas, with the frame margin around it.
            for (dvec2 corner : {dvec2(0, 0), dvec2(kW, 0), dvec2(0, kH), dvec2(kW, kH)}) {
                const dvec2 p = restingPixel(book, camera, false, corner);
                EXPECT_GT(p.x, 10.0) << name(binding);
                EXPECT_LT(p.x, kCanvasW - 10.0) << name(binding);
                EXPECT_GT(p.y, 10.0) << name(binding);
                EXPECT_LT(p.y, kCanvasH - 10.0) << name(binding);
            }
        }
    }
}

TEST(PageDragNative, APressTakesHoldOfTheLeafUnderItForEverySpinePosition) {
    for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
        Book book = makeBook(binding, Display::Double);
        book.jumpTo(2);
        const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
        // Bottom free corner of the unturned page: forward, from the apex end, at the corner.
        auto grip = gripAt(book, camera, restingPixel(book, camera, false, {kW * 0.98, kH * 0.02}));
        ASSERT_TRUE(grip) << name(binding);
        EXPECT_FALSE(grip->backward);
        EXPECT_FALSE(grip->flippedY);
        EXPECT_TRUE(grip->nearCorner);
        EXPECT_NEAR(grip->pagePoint.x, kW * 0.98, 1e-9);
        EXPECT_NEAR(grip->pagePoint.y, kH * 0.02, 1e-9);
        // Top free corner: flipped, y measured from the far end.
        grip = gripAt(book, camera, restingPixel(book, camera, false, {kW * 0.97, kH * 0.95}));
        ASSERT_TRUE(grip);
        EXPECT_TRUE(grip->flippedY);
        EXPECT_NEAR(grip->pagePoint.y, kH * 0.05, 1e-9);
        // The middle of the page: held, but no hover hint.
        grip = gripAt(book, camera, restingPixel(book, camera, false, {kW * 0.5, kH * 0.4}));
        ASSERT_TRUE(grip);
        EXPECT_FALSE(grip->nearCorner);
        // The turned page: backward.
        grip = gripAt(book, camera, restingPixel(book, camera, true, {kW * 0.9, kH * 0.1}));
        ASSERT_TRUE(grip) << name(binding);
        EXPECT_TRUE(grip->backward);
        EXPECT_NEAR(grip->pagePoint.x, kW * 0.9, 1e-9);
        // Off the pages: nothing.
        EXPECT_FALSE(gripAt(book, camera, restingPixel(book, camera, false, {kW * 1.3, kH * 0.5})));
        // At the ends of the book there is nothing to turn that way.
        book.jumpTo(0);
        EXPECT_FALSE(gripAt(book, camera, restingPixel(book, camera, true, {kW * 0.5, kH * 0.5})));
        book.jumpTo(book.lastPosition());
        EXPECT_FALSE(gripAt(book, camera, restingPixel(book, camera, false, {kW * 0.5, kH * 0.5})));
    }
}

TEST(PageDragNative, SingleDisplayTakesThePreviousLeafByItsEdgeNearTheSpine) {
    Book book = makeBook(Binding::Left, Display::Single);
    book.jumpTo(3);
    const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
    auto grip = gripAt(book, camera, restingPixel(book, camera, false, {kW * 0.05, kH * 0.3}));
    ASSERT_TRUE(grip);
    EXPECT_TRUE(grip->backward);
    EXPECT_NEAR(grip->pagePoint.x, kW, 1e-12);
    EXPECT_NEAR(grip->pagePoint.y, kH * 0.3, 1e-9);
    grip = gripAt(book, camera, restingPixel(book, camera, false, {kW * 0.6, kH * 0.3}));
    ASSERT_TRUE(grip);
    EXPECT_FALSE(grip->backward);
}

struct DragResult {
    double worstError = 0.0;       // solver's own figure
    double worstDrawnError = 0.0;  // measured through LeafDraw, as drawn
    std::vector<double> errors;    // per step, as drawn
};

// Holds the leaf by the point under the first pixel and drags it through the pixels in `path`.
DragResult drag(Book& book, const BookCamera& camera, const std::vector<dvec2>& path) {
    DragResult result;
    const auto grip = gripAt(book, camera, path.front());
    EXPECT_TRUE(grip);
    if (!grip) return result;
    EXPECT_TRUE(book.startHeldTurn(grip->backward ? TurnDirection::Backward : TurnDirection::Forward, grip->flippedY));
    for (size_t i = 1; i < path.size(); ++i) {
        const DragPose solved = solveDragPose(book, camera, *grip, path[i], book.heldPose());
        book.setHeldPose(solved.pose);
        const double drawn = glm::length(drawnGripPixel(book, camera, *grip) - path[i]);
        result.worstError = std::max(result.worstError, solved.errorPixels);
        result.worstDrawnError = std::max(result.worstDrawnError, drawn);
        result.errors.push_back(drawn);
    }
    return result;
}

std::string where(Binding binding, bool top, bool backward) {
    return std::string(name(binding)) + (top ? " top" : " bottom") + (backward ? " backward" : " forward");
}

TEST(PageDragNative, APointerTracingTheScheduledCornerIsFollowedWithinAHalfPixelForEverySpineAndCorner) {
    // The pixels a corner passes through during an animated turn are reachable by construction; a
    // pointer moving through them (at 200 points, as a hand would) must have the corner under it.
    for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
        for (bool top : {false, true}) {
            for (bool backward : {false, true}) {
                Book book = makeBook(binding, Display::Double);
                book.jumpTo(2);
                const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
                Grip corner;
                corner.backward = backward;
                corner.flippedY = top;
                corner.pagePoint = {kW * 0.99, kH * 0.01};
                std::vector<dvec2> path;
                for (int i = 0; i <= 200; ++i) {
                    path.push_back(gripPixel(book, camera, corner, book.scheduledPose(2, 0.9 * i / 200.0)));
                }
                const DragResult r = drag(book, camera, path);
                EXPECT_LT(r.worstError, 0.5) << where(binding, top, backward);
                EXPECT_LT(r.worstDrawnError, 0.5) << where(binding, top, backward);
                EXPECT_GT(book.heldPose().rho, kPi * 0.6) << where(binding, top, backward);
            }
        }
    }
}

// The smallest distance from `pointer` that any pose in the solver's domain puts the grip at, with
// the grabbed point in sight: brute force over theta, apex and rho.
double nearestReachable(const Book& book, const BookCamera& camera, const Grip& grip, dvec2 pointer) {
    double nearest = 1e300;
    for (int ci = 0; ci <= 20; ++ci) {
        for (int bi = 0; bi <= 16; ++bi) {
            for (int ri = 0; ri <= 90; ++ri) {
                const CurlParams pose{std::acos(std::cos(0.08) * ci / 20.0),
                                      -kH * std::exp(std::log(0.05) + (std::log(15.0) - std::log(0.05)) * bi / 16.0),
                                      kPi * ri / 90.0};
                if (!gripVisible(book, camera, grip, pose)) continue;
                nearest = std::min(nearest, glm::length(gripPixel(book, camera, grip, pose) - pointer));
            }
        }
    }
    return nearest;
}

TEST(PageDragNative, AStraightDragAcrossTheSpreadStaysAsCloseAsAnyPoseCanAndEndsUnderThePointer) {
    Book book = makeBook(Binding::Left, Display::Double);
    book.jumpTo(2);
    const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
    const dvec2 start = restingPixel(book, camera, false, {kW * 0.99, kH * 0.01});
    const dvec2 end = restingPixel(book, camera, true, {kW * 0.9, kH * 0.1});
    std::vector<dvec2> path;
    for (int i = 0; i <= 120; ++i) path.push_back(start + (end - start) * (i / 120.0));
    const DragResult r = drag(book, camera, path);
    const Grip grip = *gripAt(makeBook(Binding::Left, Display::Double), camera, start);
    Book probe = makeBook(Binding::Left, Display::Double);
    probe.jumpTo(2);
    // Where the solver is off the pointer, brute force finds no pose much nearer (a straight pull
    // inwards from a flat page, and a stretch past the spine, are partly out of a cone's reach).
    for (size_t i = 0; i < r.errors.size(); i += 10) {
        if (r.errors[i] < 1.0) continue;
        EXPECT_LE(r.errors[i], nearestReachable(probe, camera, grip, path[i + 1]) + 1.5) << "step " << i + 1;
    }
    // Once over the other page the corner is under the pointer again.
    EXPECT_LT(r.errors.back(), 0.5);
    EXPECT_GT(book.heldPose().rho, kPi * 0.6);
}

TEST(PageDragNative, APointerOutOfReachGetsTheNearestReachablePose) {
    Book book = makeBook(Binding::Left, Display::Double);
    book.jumpTo(1);
    const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
    const dvec2 start = restingPixel(book, camera, false, {kW, 0.0});
    auto grip = gripAt(book, camera, start);
    ASSERT_TRUE(grip);
    ASSERT_TRUE(book.startHeldTurn(TurnDirection::Forward, false));
    // Far above the book, and far out to the right.
    for (dvec2 pointer : {dvec2(start.x - 150.0, -800.0), dvec2(start.x + 500.0, start.y + 40.0)}) {
        DragPose solved{book.heldPose(), 0.0};
        for (int i = 1; i <= 40; ++i) {  // approach it as a pointer would
            solved = solveDragPose(book, camera, *grip, start + (pointer - start) * (i / 40.0), solved.pose);
        }
        EXPECT_GT(solved.errorPixels, 5.0);
        EXPECT_LE(solved.errorPixels, nearestReachable(book, camera, *grip, pointer) + 1.0);
        EXPECT_NEAR(glm::length(gripPixel(book, camera, *grip, solved.pose) - pointer), solved.errorPixels, 1e-6);
    }
}

TEST(PageDragNative, AHardLeafStaysFlatAndOnlyRotates) {
    Book book = makeBook(Binding::Left, Display::Double, 10, {true});
    const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
    const dvec2 from = restingPixel(book, camera, false, {kW, kH * 0.45});
    const dvec2 to = restingPixel(book, camera, false, {kW * 0.3, kH * 0.45});
    std::vector<dvec2> path;
    for (int i = 0; i <= 30; ++i) path.push_back(from + (to - from) * (i / 30.0));
    const DragResult r = drag(book, camera, path);
    EXPECT_DOUBLE_EQ(book.heldPose().theta, kPi / 2);
    EXPECT_GT(book.heldPose().rho, 0.5);
    // A rigid leaf cannot keep an edge point under a pointer moving straight in across it (its
    // projection only shortens), but it gets close: within the perspective's reach.
    EXPECT_LT(r.worstError, 20.0);
}

TEST(PageDragNative, ReleaseCompletesPastTheSpineOrWhenFlungOnAndFallsBackOtherwise) {
    Book book = makeBook(Binding::Left, Display::Double);
    book.jumpTo(1);
    const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
    auto grip = gripAt(book, camera, restingPixel(book, camera, false, {kW, 0.0}));
    ASSERT_TRUE(grip);
    const dvec2 shortOfSpine = restingPixel(book, camera, false, {kW * 0.4, 0.1});
    const dvec2 pastSpine = restingPixel(book, camera, true, {kW * 0.2, 0.1});
    const dvec2 still(0.0, 0.0);
    const dvec2 towardSpine = (pastSpine - shortOfSpine) * 4.0;  // fast, towards the other side
    EXPECT_FALSE(shouldCompleteTurn(book, camera, *grip, shortOfSpine, still));
    EXPECT_TRUE(shouldCompleteTurn(book, camera, *grip, pastSpine, still));
    EXPECT_TRUE(shouldCompleteTurn(book, camera, *grip, shortOfSpine, towardSpine));
    EXPECT_FALSE(shouldCompleteTurn(book, camera, *grip, pastSpine, -towardSpine));
    EXPECT_FALSE(shouldCompleteTurn(book, camera, *grip, shortOfSpine, towardSpine * 0.05));  // a slow drift
}

TEST(PageDragNative, SingleDisplayReleaseCompletesPastTheMiddleOfThePageOrWhenFlungOnForEverySpineAndDirection) {
    for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
        for (bool backward : {false, true}) {
            Book book = makeBook(binding, Display::Single);
            book.jumpTo(3);
            const BookCamera camera = bookCamera(book.config(), 390, 780);
            // Forward: the free edge near the bottom corner; backward: the spine-side quarter takes the previous leaf.
            const auto grip = gripAt(book, camera, restingPixel(book, camera, false, {backward ? kW * 0.1 : kW * 0.98, kH * 0.2}));
            ASSERT_TRUE(grip) << where(binding, false, backward);
            ASSERT_EQ(grip->backward, backward) << where(binding, false, backward);
            // Points on the page shown, by their distance from the spine: the turn's far side is the spine
            // for a forward turn and the free edge for a backward one.
            auto at = [&](double fromSpine) { return restingPixel(book, camera, false, {fromSpine * kW, kH * 0.2}); };
            const dvec2 onFar = at(backward ? 0.6 : 0.4);   // let go past the middle
            const dvec2 onNear = at(backward ? 0.4 : 0.6);  // let go before it
            const dvec2 still(0.0, 0.0);
            const dvec2 flingOn = (onFar - onNear) * 10.0;  // 2 page widths a second towards the far side
            const std::string w = where(binding, false, backward);
            EXPECT_TRUE(shouldCompleteTurn(book, camera, *grip, onFar, still)) << w;
            EXPECT_FALSE(shouldCompleteTurn(book, camera, *grip, onNear, still)) << w;
            EXPECT_TRUE(shouldCompleteTurn(book, camera, *grip, onNear, flingOn)) << w;
            EXPECT_FALSE(shouldCompleteTurn(book, camera, *grip, onFar, -flingOn)) << w;
            // The same fling threshold as double display: a slow drift (0.2 page widths a second) decides nothing.
            EXPECT_FALSE(shouldCompleteTurn(book, camera, *grip, onNear, flingOn * 0.1)) << w;
            EXPECT_TRUE(shouldCompleteTurn(book, camera, *grip, onFar, -flingOn * 0.1)) << w;
        }
    }
}

TEST(BookCameraNative, ASinglePageFillsItsBoxWhateverItsShapeAndASpreadKeepsItsMargin) {
    // Phone boxes, portrait and landscape, and page shapes from tall to wide.
    for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
        for (dvec2 page : {dvec2(0.8, 1.0), dvec2(0.5, 1.0), dvec2(1.4, 1.0)}) {
            for (dvec2 box : {dvec2(374, 468), dvec2(828, 300), dvec2(300, 300)}) {
                BookConfig config;
                config.pageCount = 10;
                config.display = Display::Single;
                config.binding = binding;
                config.pageWidth = page.x;
                config.pageHeight = page.y;
                const BookCamera camera = bookCamera(config, static_cast<int>(box.x), static_cast<int>(box.y));
                const PixelRect r = restingRect(camera, config);
                // The dimension the box limits: the larger of the two fractions.
                const double fill = std::max(r.width / box.x, r.height / box.y);
                EXPECT_NEAR(fill, 1.0 / kSingleFrameMargin, 1e-9) << name(binding) << " " << page.x << " " << box.x;
                EXPECT_GE(fill, 0.92);
                config.display = Display::Double;
                const PixelRect spread = restingRect(bookCamera(config, static_cast<int>(box.x), static_cast<int>(box.y)), config);
                EXPECT_NEAR(std::max(spread.width / box.x, spread.height / box.y), 1.0 / kFrameMargin, 1e-9);
            }
        }
    }
}

CurlParams flyingPose(const Book& book) {
    const BookFrame frame = book.frame();
    for (int i = 0; i < frame.count; ++i) {
        if (!frame.leaves[i].resting) return frame.leaves[i].curl;
    }
    ADD_FAILURE() << "no leaf in flight";
    return {};
}

TEST(PageDragNative, AReleasedTurnCarriesOnFromItsPoseWithNoJumpAndLands) {
    for (bool complete : {true, false}) {
        Book book = makeBook(Binding::Left, Display::Double);
        book.jumpTo(2);
        ASSERT_TRUE(book.startHeldTurn(TurnDirection::Forward, true));
        EXPECT_EQ(book.position(), 3);
        EXPECT_FALSE(book.startTurn(TurnDirection::Forward));  // nothing turns over a held leaf
        const CurlParams held{0.5, -1.2 * kH, 1.3};
        book.setHeldPose(held);
        EXPECT_TRUE(book.frame().leaves[book.frame().count - 1].flippedY);
        book.advance(0.5);  // time does not move a held leaf
        EXPECT_DOUBLE_EQ(flyingPose(book).rho, held.rho);
        book.releaseHeldTurn(complete);
        EXPECT_FALSE(book.holding());
        EXPECT_EQ(book.position(), complete ? 3 : 2);
        const CurlParams released = flyingPose(book);
        EXPECT_NEAR(released.theta, held.theta, 1e-12);
        EXPECT_NEAR(released.apexY, held.apexY, 1e-12);
        EXPECT_NEAR(released.rho, held.rho, 1e-12);
        // Small steps change the pose a little at a time: no jump, and it heads the right way.
        CurlParams previous = released;
        double largestStep = 0.0;
        int steps = 0;
        while (book.animating() && steps < 1000) {
            book.advance(0.004);
            if (!book.animating()) break;
            const CurlParams pose = flyingPose(book);
            largestStep = std::max({largestStep, std::abs(pose.rho - previous.rho), std::abs(pose.theta - previous.theta)});
            EXPECT_TRUE(complete ? pose.rho >= previous.rho : pose.rho <= previous.rho);
            previous = pose;
            ++steps;
        }
        EXPECT_FALSE(book.animating()) << "the turn never landed";
        EXPECT_LT(largestStep, 0.06);
        EXPECT_EQ(book.position(), complete ? 3 : 2);
        EXPECT_EQ(book.frame().count, 2);
    }
}

TEST(PageDragNative, AReleasedTurnStaysBetweenItsReleasedConeAndTheSchedulesNeverRollingIntoATube) {
    // A fling (a tight cone let go early) once flew through theta 0 and an apex above the page: the leaf
    // rolled into a tube of hundreds of turns, and llvmpipe took seconds to draw the frame (Firefox, WebKit).
    const CurlSchedule schedule;
    const double tightestTheta = std::min(schedule.thetaPhase1, schedule.thetaPhase2);
    const double nearestApex = std::max(schedule.apexPhase1, schedule.apexPhase2) * kH;
    int checked = 0;
    for (bool complete : {true, false}) {
        for (double theta : {0.08, 0.2, 0.5, 1.0, 1.5}) {
            for (double apex : {-0.05, -0.3, -1.0, -5.0, -40.0}) {
                for (double rho : {0.05, 0.3, 1.0, 2.0, 3.0}) {
                    Book book = makeBook(Binding::Left, Display::Double);
                    book.jumpTo(2);
                    ASSERT_TRUE(book.startHeldTurn(TurnDirection::Forward, false));
                    const CurlParams held{theta, apex * kH, rho};
                    book.setHeldPose(held);
                    book.releaseHeldTurn(complete);
                    for (int steps = 0; book.animating() && steps < 2000; ++steps) {
                        const CurlParams pose = flyingPose(book);
                        EXPECT_GE(pose.theta, std::min(theta, tightestTheta) - 1e-9) << theta << " " << apex << " " << rho;
                        EXPECT_LE(pose.apexY, std::max(apex * kH, nearestApex) + 1e-9) << theta << " " << apex << " " << rho;
                        ++checked;
                        book.advance(0.004);
                    }
                    EXPECT_FALSE(book.animating());
                }
            }
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(PageDragNative, TheHoverHintLiftsTheCornerSlightlyAndStartsFlat) {
    Book book = makeBook(Binding::Left, Display::Double);
    const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
    auto grip = gripAt(book, camera, restingPixel(book, camera, false, {kW, 0.0}));
    ASSERT_TRUE(grip);
    const CurlParams none = hoverHintPose(book, *grip, 0.0);
    EXPECT_NEAR(curlPoint({kW, 0.0}, none).z, 0.0, 1e-9);
    const CurlParams full = hoverHintPose(book, *grip, 1.0);
    const double lift = curlPoint({kW, 0.0}, full).z;
    EXPECT_NEAR(lift, 0.08 * kH, 1e-3 * kH);
    EXPECT_LT(curlPoint({kW, kH}, full).z, lift * 0.5);  // the corner, not the whole edge
    EXPECT_LT(hoverHintPose(book, *grip, 0.5).theta, none.theta);
}

}  // namespace

namespace {

TEST(BookCameraNative, ZoomingAboutAPixelKeepsTheTablePointUnderItAndStaysWithinTheLimits) {
    Book book = makeBook(Binding::Left, Display::Double);
    const dvec2 pixel(700.0, 420.0);
    const dvec3 before = pixelToTable(bookCamera(book.config(), kCanvasW, kCanvasH, book.zoom()), pixel);
    for (double scale : {1.5, 2.0, 3.7, 4.0}) {
        book.setZoom(zoomAbout(book.zoom(), scale, pixel, kCanvasW, kCanvasH));
        const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH, book.zoom());
        const dvec2 again = worldToPixel(camera, before);
        EXPECT_NEAR(again.x, pixel.x, 1e-6) << scale;
        EXPECT_NEAR(again.y, pixel.y, 1e-6) << scale;
        EXPECT_DOUBLE_EQ(book.zoom().scale, scale);
        EXPECT_NEAR(camera.pixelsPerUnit, scale * bookCamera(book.config(), kCanvasW, kCanvasH).pixelsPerUnit, 1e-9);
    }
    // Out of range: scale kept in [1, 4]; the offset never lets the view run off the pages' frame.
    book.setZoom(ViewZoom{9.0, 50.0, -50.0});
    EXPECT_EQ(book.zoom().scale, kMaxZoom);
    EXPECT_EQ(book.zoom().offsetX, kMaxZoom - 1.0);
    EXPECT_EQ(book.zoom().offsetY, 1.0 - kMaxZoom);
    book.setZoom(ViewZoom{std::nan(""), 0.3, 0.0});
    EXPECT_EQ(book.zoom().scale, 1.0);
    EXPECT_EQ(book.zoom().offsetX, 0.0);
    // Grips and drags work in the zoomed view: a press on the zoomed corner finds the corner.
    book.jumpTo(2);
    book.setZoom(zoomAbout(ViewZoom{}, 2.5, {800.0, 500.0}, kCanvasW, kCanvasH));
    const BookCamera zoomed = bookCamera(book.config(), kCanvasW, kCanvasH, book.zoom());
    const auto grip = gripAt(book, zoomed, restingPixel(book, zoomed, false, {kW * 0.95, kH * 0.05}));
    ASSERT_TRUE(grip);
    EXPECT_NEAR(grip->pagePoint.x, kW * 0.95, 1e-9);
}

TEST(BookCameraNative, PanningMovesTheZoomedPictureWithThePointerAndStopsWhereThePagesEnd) {
    Book book = makeBook(Binding::Left, Display::Double);
    const ViewZoom zoomed = zoomAbout(ViewZoom{}, 2.0, {kCanvasW / 2.0, kCanvasH / 2.0}, kCanvasW, kCanvasH);
    const dvec2 pixel(600.0, 400.0);
    const dvec3 table = pixelToTable(bookCamera(book.config(), kCanvasW, kCanvasH, zoomed), pixel);
    const ViewZoom panned = panBy(zoomed, {30.0, -20.0}, kCanvasW, kCanvasH);
    const dvec2 moved = worldToPixel(bookCamera(book.config(), kCanvasW, kCanvasH, panned), table);
    EXPECT_NEAR(moved.x, pixel.x + 30.0, 1e-6);
    EXPECT_NEAR(moved.y, pixel.y - 20.0, 1e-6);
    EXPECT_EQ(panned.scale, zoomed.scale);
    // A pan past the pages' frame stops at it; at 1x nothing moves; a NaN pan leaves no NaN in the view.
    EXPECT_EQ(panBy(zoomed, {1e6, -1e6}, kCanvasW, kCanvasH).offsetX, zoomed.scale - 1.0);
    EXPECT_EQ(panBy(zoomed, {1e6, -1e6}, kCanvasW, kCanvasH).offsetY, zoomed.scale - 1.0);
    EXPECT_EQ(panBy(ViewZoom{}, {50.0, 50.0}, kCanvasW, kCanvasH).offsetX, 0.0);
    EXPECT_TRUE(std::isfinite(panBy(zoomed, {std::nan(""), 0.0}, kCanvasW, kCanvasH).offsetX));
}

TEST(BookCameraNative, TheRestingRectangleIsTheProjectedViewFrameCenteredWithRoomAround) {
    for (Display display : {Display::Double, Display::Single}) {
        Book book = makeBook(Binding::Left, display);
        const BookCamera camera = bookCamera(book.config(), kCanvasW, kCanvasH);
        const PixelRect r = restingRect(camera, book.config());
        EXPECT_NEAR(r.x + r.width / 2.0, kCanvasW / 2.0, 1e-6);
        EXPECT_NEAR(r.y + r.height / 2.0, kCanvasH / 2.0, 1e-6);
        EXPECT_LT(r.width, kCanvasW);
        EXPECT_LT(r.height, kCanvasH);
        // The open page's corners lie on its edges.
        const dvec2 corner = restingPixel(book, camera, false, {kW, kH});
        EXPECT_TRUE(std::abs(corner.x - (r.x + r.width)) < 1e-6 || std::abs(corner.x - r.x) < 1e-6) << corner.x;
        const double aspect = display == Display::Double ? 2.0 * kW / kH : kW / kH;
        EXPECT_NEAR(r.width / r.height, aspect, 1e-6);
    }
}

}  // namespace
