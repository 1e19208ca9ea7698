// Native (GoogleTest via CTest) tests of motions of the whole book: riffling to a far position (several
// leaves in flight, landing within kRiffleSpan turns), a closed book centred in the view, and the view
// of a single page leaving the spine's side room while a leaf turns.
#include "book.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "book_camera.hpp"
#include "book_stacks.hpp"
#include "leaf_placement.hpp"
#include "page_drag.hpp"

namespace {

using conecurl::Binding;
using conecurl::Book;
using conecurl::BookConfig;
using conecurl::BookFrame;
using conecurl::Display;
using conecurl::kMaxTurnsInFlight;
using conecurl::kRiffleSpan;

constexpr double kPi = 3.14159265358979323846;

// Paper of no thickness unless asked: the centre shift is then exactly half a page.
Book makeBook(int pageCount, Display display = Display::Double, Binding binding = Binding::Left, bool center = true,
              double leafThickness = 0.0) {
    BookConfig config;
    config.leafThickness = leafThickness;
    config.pageCount = pageCount;
    config.display = display;
    config.binding = binding;
    config.turnSeconds = 1.0;
    config.center = center;
    return Book(config);
}

int leavesInFlight(const BookFrame& frame) {
    int n = 0;
    for (int i = 0; i < frame.count; ++i) n += frame.leaves[i].resting ? 0 : 1;
    return n;
}

// Leaves lifted off the table: in flight and turned by more than a hair.
int leavesLifted(const BookFrame& frame) {
    int n = 0;
    for (int i = 0; i < frame.count; ++i) n += !frame.leaves[i].resting && frame.leaves[i].curl.rho > 1e-6 ? 1 : 0;
    return n;
}

TEST(Riffle, FromPageZeroToThreeHundredOfFourHundredLandsWithinTheSpanWithSeveralLeavesLifted) {
    Book book = makeBook(400);
    const int target = book.positionOfPage(300);
    ASSERT_TRUE(book.riffleTo(target));
    EXPECT_EQ(book.position(), target);  // where it will settle, at once, as startTurn does
    int mostLifted = 0;
    double seconds = 0.0;
    const double step = 1.0 / 60.0;
    while (book.animating() && seconds < 10.0) {
        mostLifted = std::max(mostLifted, leavesLifted(book.frame()));
        book.advance(step);
        seconds += step;
    }
    EXPECT_FALSE(book.animating());
    EXPECT_LE(seconds, kRiffleSpan + step);
    EXPECT_LE(kRiffleSpan, 2.0);  // the bound: twice one turn
    EXPECT_GE(mostLifted, 3);
    EXPECT_EQ(book.firstVisiblePage(), 299);
    EXPECT_EQ(book.frame().count, 2);  // at rest: the two stacks' top leaves
}

TEST(Riffle, LeavesInFlightAreSpreadOverTheWayFirstFromTheTopLastLandingAtTheTarget) {
    Book book = makeBook(400);
    book.jumpTo(10);
    ASSERT_TRUE(book.riffleTo(150));
    const BookFrame frame = book.frame();
    std::set<int> flying;
    for (int i = 0; i < frame.count; ++i) {
        if (!frame.leaves[i].resting) flying.insert(frame.leaves[i].leaf);
    }
    EXPECT_EQ(static_cast<int>(flying.size()), kMaxTurnsInFlight);
    EXPECT_EQ(*flying.begin(), 10);    // the leaf on top of the unturned stack goes first
    EXPECT_EQ(*flying.rbegin(), 149);  // the last lands on top of the turned stack at the target
    // The stacks: the turned side still shows leaf 9 (the carried leaves are out of both stacks); the
    // unturned side is the target's leaf, under the waiting ones.
    for (int i = 0; i < frame.count; ++i) {
        if (!frame.leaves[i].resting) continue;
        if (frame.leaves[i].curl.rho > 1.0) EXPECT_EQ(frame.leaves[i].leaf, 9);
        else EXPECT_EQ(frame.leaves[i].leaf, 150);
    }
}

TEST(Riffle, TheTurnedStackTopIsAlwaysTheLastLeafLandedSoNoPageJumpsAhead) {
    Book book = makeBook(400);
    ASSERT_TRUE(book.riffleTo(120));
    int lastTop = -1;
    for (int frameIndex = 0; frameIndex < 200 && book.animating(); ++frameIndex) {
        book.advance(1.0 / 60.0);
        const BookFrame frame = book.frame();
        for (int i = 0; i < frame.count; ++i) {
            const auto& leaf = frame.leaves[i];
            if (leaf.resting && leaf.curl.rho > 1.0) {
                EXPECT_GE(leaf.leaf, lastTop);  // grows as leaves land, never skips back
                lastTop = leaf.leaf;
            }
        }
    }
    EXPECT_EQ(lastTop, 119);
}

TEST(Riffle, BackwardToTheFrontCoverAndSingleDisplayLandAtTheTarget) {
    Book book = makeBook(400);
    book.jumpTo(150);
    ASSERT_TRUE(book.riffleTo(0));
    while (book.animating()) book.advance(0.05);
    EXPECT_EQ(book.position(), 0);
    EXPECT_EQ(book.firstVisiblePage(), 0);

    Book single = makeBook(50, Display::Single);
    ASSERT_TRUE(single.riffleTo(49));
    EXPECT_GE(leavesInFlight(single.frame()), 2);
    while (single.animating()) single.advance(0.05);
    EXPECT_EQ(single.firstVisiblePage(), 49);
}

TEST(Riffle, IsRefusedOneLeafAwayWhileALeafMovesOrIsHeldAndClampsTheTarget) {
    Book book = makeBook(40);
    EXPECT_FALSE(book.riffleTo(1));  // one leaf: a plain turn
    EXPECT_FALSE(book.riffleTo(0));
    ASSERT_TRUE(book.startTurn(conecurl::TurnDirection::Forward));
    EXPECT_FALSE(book.riffleTo(15));  // a leaf in flight
    while (book.animating()) book.advance(0.1);
    ASSERT_TRUE(book.startHeldTurn(conecurl::TurnDirection::Forward, false));
    EXPECT_FALSE(book.riffleTo(15));  // a held leaf
    book.releaseHeldTurn(false);
    while (book.animating()) book.advance(0.1);
    EXPECT_EQ(book.position(), 1);
    ASSERT_TRUE(book.riffleTo(1000));
    EXPECT_EQ(book.position(), book.lastPosition());
    // Turns asked for during a riffle wait: all six slots are taken.
    EXPECT_FALSE(book.startTurn(conecurl::TurnDirection::Forward));
}

TEST(Riffle, CarriedLeavesAreInNeitherStackSoTheStacksGrowAsLeavesLandNotWhenTheRiffleStarts) {
    Book book = makeBook(400);
    book.jumpTo(20);
    ASSERT_TRUE(book.riffleTo(120));
    conecurl::StackLeaves s = conecurl::stackLeaves(book);
    EXPECT_EQ(s.turned, 20);        // as before the riffle: nothing has landed yet
    EXPECT_EQ(s.unturned, 200 - 120);  // the leaves from the target on
    int lastTurned = s.turned;
    while (book.animating()) {
        book.advance(1.0 / 60.0);
        s = conecurl::stackLeaves(book);
        EXPECT_GE(s.turned, lastTurned);
        lastTurned = s.turned;
    }
    EXPECT_EQ(lastTurned, 120);
}

TEST(Riffle, FewerLeavesThanSlotsTurnEachOnce) {
    Book book = makeBook(40);
    ASSERT_TRUE(book.riffleTo(3));
    std::set<int> flying;
    const BookFrame frame = book.frame();
    for (int i = 0; i < frame.count; ++i) {
        if (!frame.leaves[i].resting) flying.insert(frame.leaves[i].leaf);
    }
    EXPECT_EQ(flying, (std::set<int>{0, 1, 2}));
}

TEST(CenterShift, AClosedBookSitsHalfAPageTowardsItsOneCoverAndAnOpenOneDoesNot) {
    for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
        Book book = makeBook(8, Display::Double, binding);
        const double w = book.config().pageWidth;
        EXPECT_DOUBLE_EQ(book.centerShift(), 0.5 * w);  // front cover alone on the unturned side
        EXPECT_DOUBLE_EQ(book.settledCenterShift(), 0.5 * w);
        book.jumpTo(2);
        EXPECT_DOUBLE_EQ(book.centerShift(), 0.0);
        book.jumpTo(book.lastPosition());
        EXPECT_DOUBLE_EQ(book.centerShift(), -0.5 * w);  // back cover alone on the turned side
        EXPECT_DOUBLE_EQ(book.settledCenterShift(), -0.5 * w);
    }
    Book off = makeBook(8, Display::Double, Binding::Left, false);
    EXPECT_EQ(off.centerShift(), 0.0);
    Book single = makeBook(8, Display::Single);
    EXPECT_EQ(single.centerShift(), 0.0);
}

TEST(CenterShift, SlidesSmoothlyAndMonotonicallyAsTheCoverOpensAndBackAsItCloses) {
    Book book = makeBook(8);
    const double w = book.config().pageWidth;
    ASSERT_TRUE(book.startTurn(conecurl::TurnDirection::Forward));
    EXPECT_NEAR(book.centerShift(), 0.5 * w, 1e-12);  // no jump as the turn starts
    EXPECT_NEAR(book.settledCenterShift(), 0.0, 1e-12);  // where it will be
    double last = book.centerShift();
    double biggestStep = 0.0;
    while (book.animating()) {
        book.advance(1.0 / 60.0);
        const double now = book.centerShift();
        EXPECT_LE(now, last + 1e-12);
        biggestStep = std::max(biggestStep, last - now);
        last = now;
    }
    EXPECT_NEAR(last, 0.0, 1e-12);  // no jump as it lands
    EXPECT_LT(biggestStep, 0.05 * w);  // a slide, not a cut: at 60 frames a second, 1 s turn
    ASSERT_TRUE(book.startTurn(conecurl::TurnDirection::Backward));
    while (book.animating()) {
        book.advance(1.0 / 60.0);
        EXPECT_GE(book.centerShift(), last - 1e-12);
        last = book.centerShift();
    }
    EXPECT_NEAR(last, 0.5 * w, 1e-12);
}

TEST(CenterShift, WithThicknessAClosedBookCentresItsPageAndTheEdgeBandOfTheStackUnderIt) {
    for (int pages : {8, 400}) {
        Book book = makeBook(pages, Display::Double, Binding::Left, true, 0.01);
        const double w = book.config().pageWidth;
        const conecurl::Stacks closed = conecurl::bookStacks(book.config(), conecurl::stackLeaves(book), 0.01);
        ASSERT_GT(closed.unturned.total(), 0.0);
        EXPECT_EQ(closed.turned.total(), 0.0);
        EXPECT_DOUBLE_EQ(book.centerShift(), 0.5 * (w + closed.unturned.total())) << pages << " pages";
        EXPECT_DOUBLE_EQ(book.settledCenterShift(), book.centerShift());
        book.jumpTo(2);
        EXPECT_EQ(book.centerShift(), 0.0);  // open: where it always was
        book.jumpTo(book.lastPosition());
        const conecurl::Stacks back = conecurl::bookStacks(book.config(), conecurl::stackLeaves(book), 0.01);
        EXPECT_DOUBLE_EQ(book.centerShift(), -0.5 * (w + back.turned.total()));
        // Turning the cover over: the settled shift is where the turn lands, mid-turn it slides.
        book.jumpTo(1);
        ASSERT_TRUE(book.startTurn(conecurl::TurnDirection::Backward));
        EXPECT_DOUBLE_EQ(book.settledCenterShift(), 0.5 * (w + closed.unturned.total()));
        EXPECT_NEAR(book.centerShift(), 0.0, 1e-12);
    }
    Book thin = makeBook(8);
    thin.setLeafThickness(std::nan(""));
    EXPECT_EQ(thin.config().leafThickness, 0.0);
    thin.setLeafThickness(1.0);
    EXPECT_EQ(thin.config().leafThickness, conecurl::kMaxLeafThickness);
}

TEST(CenterShift, ADraggedCoverIsSolvedThroughTheCameraOfItsOwnPoseSoItsCornerStaysUnderThePointer) {
    for (Binding binding : {Binding::Left, Binding::Right}) {
        Book book = makeBook(8, Display::Double, binding, true, 0.004);
        const conecurl::BookCamera rest = conecurl::bookCamera(book, 800, 600);
        const conecurl::OpenPages open = conecurl::openPagePlaces(book, rest);
        const conecurl::PixelRect r = open.places[0].rect;
        const double freeX = binding == Binding::Left ? r.x + r.width - 2.0 : r.x + 2.0;
        const auto grip = conecurl::gripAt(book, rest, {freeX, r.y + r.height - 2.0});
        ASSERT_TRUE(grip);
        ASSERT_TRUE(book.startHeldTurn(conecurl::TurnDirection::Forward, grip->flippedY));
        double worstSliding = 0.0;
        double worstFixed = 0.0;
        for (int i = 1; i <= 10; ++i) {
            // Where the corner is drawn at a pose of the turn: through the camera of that pose.
            const conecurl::CurlParams target = book.scheduledPose(0, 0.08 * i);
            const conecurl::BookCamera seen = conecurl::bookCamera(book.config(), 800, 600, book.zoom(), book.centerShiftHolding(target));
            const glm::dvec2 pointer = conecurl::gripPixel(book, seen, *grip, target);
            const conecurl::DragPose sliding = conecurl::solveSlidingDragPose(book, 800, 600, *grip, pointer, book.heldTarget());
            const conecurl::DragPose fixed = conecurl::solveDragPose(book, conecurl::bookCamera(book, 800, 600), *grip, pointer, book.heldTarget());
            book.setHeldPose(sliding.pose);
            const glm::dvec2 drawn = conecurl::gripPixel(book, conecurl::bookCamera(book, 800, 600), *grip, book.heldPose());
            worstSliding = std::max(worstSliding, glm::length(drawn - pointer));
            const conecurl::BookCamera fixedSeen = conecurl::bookCamera(book.config(), 800, 600, book.zoom(), book.centerShiftHolding(fixed.pose));
            worstFixed = std::max(worstFixed, glm::length(conecurl::gripPixel(book, fixedSeen, *grip, fixed.pose) - pointer));
        }
        EXPECT_LT(worstSliding, 0.05);  // pixels
        EXPECT_GT(worstFixed, 1.0);     // solving through the camera of the pose before would miss it
    }
}

TEST(CenterShift, TheCameraLooksAtTheMiddleOfWhatIsOpenSoAClosedBookHasEqualMargins) {
    for (Binding binding : {Binding::Left, Binding::Right}) {
        Book book = makeBook(8, Display::Double, binding);
        for (int position : {0, 4}) {
            book.jumpTo(position);
            const conecurl::BookCamera camera = conecurl::bookCamera(book, 800, 600);
            const conecurl::OpenPages open = conecurl::openPagePlaces(book, camera);
            ASSERT_EQ(open.count, 1);
            const conecurl::PixelRect r = open.places[0].rect;
            EXPECT_NEAR(r.x, 800 - (r.x + r.width), 1e-6) << "position " << position;  // left margin = right margin
        }
        book.jumpTo(2);
        const conecurl::OpenPages both = conecurl::openPagePlaces(book, conecurl::bookCamera(book, 800, 600));
        ASSERT_EQ(both.count, 2);
        const double left = std::min(both.places[0].rect.x, both.places[1].rect.x);
        const double right = std::max(both.places[0].rect.x + both.places[0].rect.width, both.places[1].rect.x + both.places[1].rect.width);
        EXPECT_NEAR(left, 800 - right, 1e-6);  // the open book where it always was
    }
}

// A single-display book on a phone's screen (ratio 3, portrait; landscape for a calendar's spine).
struct PhoneBook {
    Book book;
    int width;
    int height;
};
PhoneBook phoneBook(Binding binding) {
    Book book = makeBook(8, Display::Single, binding);
    book.jumpTo(3);
    const bool top = binding == Binding::Top;
    return PhoneBook{book, top ? 2532 : 1170, top ? 1170 : 2532};
}

// The share of the turning leaf's paper inside the canvas at progress t, through the book's camera, and
// through the same camera with no centre shift (a view that stays where it is).
std::pair<double, double> turningShareInView(PhoneBook& phone, double t) {
    phone.book.setLatestTurnProgress(t);
    const BookFrame frame = phone.book.frame();
    const conecurl::BookConfig& c = phone.book.config();
    const conecurl::BookCamera moving = conecurl::bookCamera(phone.book, phone.width, phone.height);
    const conecurl::BookCamera still = conecurl::bookCamera(c, phone.width, phone.height, phone.book.zoom(), 0.0);
    for (int i = 0; i < frame.count; ++i) {
        if (frame.leaves[i].resting) continue;
        return {conecurl::leafShareInView(moving, c, frame.leaves[i]), conecurl::leafShareInView(still, c, frame.leaves[i])};
    }
    ADD_FAILURE() << "no leaf in flight";
    return {0.0, 0.0};
}

TEST(SingleTurnRoom, TheViewMovesTowardsTheSpineAsALeafRisesSoMostOfTheCurlStaysOnAPhonesScreen) {
    const double ts[4] = {0.15, 0.3, 0.45, 0.6};
    const double least[4] = {0.95, 0.95, 0.75, 0.6};  // a forward turn: the leaf's paper inside the canvas
    for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
        PhoneBook phone = phoneBook(binding);
        ASSERT_TRUE(phone.book.startTurn(conecurl::TurnDirection::Forward));
        for (int i = 0; i < 4; ++i) {
            const auto [moving, still] = turningShareInView(phone, ts[i]);
            EXPECT_GE(moving, least[i]) << "binding " << static_cast<int>(binding) << " t=" << ts[i];
            // A view that stayed put would lose the leaf off the spine's edge from a quarter of the way on.
            if (ts[i] >= 0.3) EXPECT_GT(moving, still + 0.3) << "binding " << static_cast<int>(binding) << " t=" << ts[i];
        }
        // A backward turn brings the leaf in from beyond the spine: in view far sooner, on the whole.
        PhoneBook back = phoneBook(binding);
        ASSERT_TRUE(back.book.startTurn(conecurl::TurnDirection::Backward));
        double moving = 0.0;
        double still = 0.0;
        for (double t : ts) {
            const auto [m, s] = turningShareInView(back, t);
            moving += m / 4.0;
            still += s / 4.0;
        }
        EXPECT_GT(moving, still + 0.1) << "binding " << static_cast<int>(binding);
        EXPECT_GT(moving, 0.7) << "binding " << static_cast<int>(binding);
    }
}

TEST(SingleTurnRoom, TheViewIsStillAtRestAndMovesWithNoJumpFromTheTurnsStartToItsLanding) {
    for (Binding binding : {Binding::Left, Binding::Right, Binding::Top}) {
        for (auto direction : {conecurl::TurnDirection::Forward, conecurl::TurnDirection::Backward}) {
            PhoneBook phone = phoneBook(binding);
            const double w = phone.book.config().pageWidth;
            EXPECT_EQ(phone.book.centerShift(), 0.0);
            ASSERT_TRUE(phone.book.startTurn(direction));
            EXPECT_NEAR(phone.book.centerShift(), 0.0, 1e-12);  // no jump as it starts
            double previous = 0.0;
            double most = 0.0;
            for (int i = 1; i <= 200; ++i) {
                phone.book.setLatestTurnProgress(i / 200.0);
                const double shift = phone.book.centerShift();
                EXPECT_LE(shift, 0.0);  // towards the turned side, where the spine's room is
                EXPECT_LT(std::abs(shift - previous), 0.02 * w) << "step " << i;  // 1/200 of the turn moves it little
                most = std::min(most, shift);
                previous = shift;
            }
            EXPECT_NEAR(most, -0.5 * w, 0.01 * w);  // half a page width as the leaf stands on its spine
            EXPECT_NEAR(phone.book.centerShift(), 0.0, 1e-9);  // back where it was as the leaf lands
            EXPECT_EQ(phone.book.settledCenterShift(), 0.0);
        }
    }
}

TEST(SingleTurnRoom, ADraggedLeafIsSolvedThroughTheCameraOfItsOwnPoseSoItsCornerStaysUnderTheFinger) {
    for (Binding binding : {Binding::Left, Binding::Right}) {
        PhoneBook phone = phoneBook(binding);
        Book& book = phone.book;
        const conecurl::BookCamera rest = conecurl::bookCamera(book, phone.width, phone.height);
        const conecurl::PixelRect r = conecurl::openPagePlaces(book, rest).places[0].rect;
        const double freeX = binding == Binding::Left ? r.x + r.width - 6.0 : r.x + 6.0;
        const auto grip = conecurl::gripAt(book, rest, {freeX, r.y + r.height - 6.0});
        ASSERT_TRUE(grip);
        ASSERT_TRUE(book.startHeldTurn(conecurl::TurnDirection::Forward, grip->flippedY));
        double worst = 0.0;
        for (int i = 1; i <= 10; ++i) {
            const conecurl::CurlParams target = book.scheduledPose(book.heldLeaf(), 0.06 * i);
            const conecurl::BookCamera seen =
                conecurl::bookCamera(book.config(), phone.width, phone.height, book.zoom(), book.centerShiftHolding(target));
            const glm::dvec2 finger = conecurl::gripPixel(book, seen, *grip, target);
            book.setHeldPose(conecurl::solveSlidingDragPose(book, phone.width, phone.height, *grip, finger, book.heldTarget()).pose);
            const glm::dvec2 drawn = conecurl::gripPixel(book, conecurl::bookCamera(book, phone.width, phone.height), *grip, book.heldPose());
            worst = std::max(worst, glm::length(drawn - finger));
        }
        EXPECT_LT(worst, 0.5) << "binding " << static_cast<int>(binding);  // device pixels
    }
}

}  // namespace
