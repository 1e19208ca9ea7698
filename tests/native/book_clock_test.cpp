// Native (GoogleTest via CTest) tests of the frame clock: capped steps, turns queued behind a leaf in
// flight and started in order, the flags a tick reports, the pages a frame shows, and how fast the
// leaves moved and which landed (LeafMotion, for the page sound).
#include "book_clock.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using namespace conecurl;

Book bookOf(int pages, Display display = Display::Double, double turnSeconds = 1.0) {
    BookConfig config;
    config.pageCount = pages;
    config.display = display;
    config.turnSeconds = turnSeconds;
    return Book(config);
}

Book hardBookOf(int pages, double turnSeconds = 1.0) {
    BookConfig config;
    config.pageCount = pages;
    config.turnSeconds = turnSeconds;
    config.hardPages.assign(pages, true);
    return Book(config);
}

// Ticks a turn forward from t = 0 every `step` seconds until it settles: each tick's motion, in order.
std::vector<LeafMotion> motionsOfATurn(Book& book, BookClock& clock, double step) {
    std::vector<LeafMotion> motions;
    clock.tick(book, -step);  // a frame before the turn: the book at rest
    clock.requestTurn(book, TurnDirection::Forward, 0.0);
    for (double t = 0.0; t < 10.0; t += step) {
        const int flags = clock.tick(book, t);
        motions.push_back(clock.motion());
        if (flags & kTickSettled) break;
    }
    return motions;
}

double peakSpeed(const std::vector<LeafMotion>& motions) {
    double peak = 0.0;
    for (const LeafMotion& m : motions) peak = std::max(peak, m.speed);
    return peak;
}

std::vector<int> pagesOf(const PagesOnScreen& p) { return {p.pages.begin(), p.pages.begin() + p.count}; }

TEST(BookClock, ATurnRunsFromWhenItWasAskedForAndTicksAdvanceByTheTimeBetweenThem) {
    Book book = bookOf(8);
    BookClock clock;
    ASSERT_EQ(clock.requestTurn(book, TurnDirection::Forward, 10.0), TurnRequest::Started);
    EXPECT_TRUE(clock.tick(book, 10.25) & kTickMoving);  // the frame it waited for counts
    EXPECT_EQ(book.position(), 1);
    EXPECT_TRUE(book.animating());
    EXPECT_TRUE(clock.tick(book, 10.5) & kTickMoving);  // half of a one-second turn
    EXPECT_TRUE(clock.tick(book, 10.75) & kTickMoving);
    EXPECT_TRUE(book.animating());
    const int flags = clock.tick(book, 11.0);           // the whole second: it lands
    EXPECT_FALSE(flags & kTickMoving);
    EXPECT_TRUE(flags & kTickSettled);
    EXPECT_FALSE(book.animating());
    EXPECT_FALSE(clock.running());
}

TEST(BookClock, AStepIsCappedSoAStalledTabDoesNotJumpAndTimeNeverRunsBackwards) {
    Book book = bookOf(8);
    BookClock clock;
    clock.requestTurn(book, TurnDirection::Forward, 0.0);
    clock.tick(book, 0.0);
    clock.tick(book, 100.0);  // a hidden tab: at most kMaxStepSeconds of the turn passes
    EXPECT_TRUE(book.animating());
    clock.tick(book, 99.0);   // a timestamp from the past advances nothing
    EXPECT_TRUE(book.animating());
    for (int i = 1; i <= 2; ++i) clock.tick(book, 100.0 + i * BookClock::kMaxStepSeconds);
    EXPECT_TRUE(book.animating());  // 0.75 s of a 1 s turn
    clock.tick(book, 100.0 + 3 * BookClock::kMaxStepSeconds);
    EXPECT_FALSE(book.animating());
}

TEST(BookClock, ATurnForALeafInFlightWaitsAndStartsInOrderWhenItCan) {
    Book book = bookOf(8);
    BookClock clock;
    ASSERT_EQ(clock.requestTurn(book, TurnDirection::Forward, 0.0), TurnRequest::Started);
    // Backward needs leaf 0, which is in flight: it waits; a forward asked after it waits behind it.
    EXPECT_EQ(clock.requestTurn(book, TurnDirection::Backward, 0.0), TurnRequest::Queued);
    EXPECT_EQ(clock.requestTurn(book, TurnDirection::Forward, 0.0), TurnRequest::Queued);
    EXPECT_EQ(clock.queuedTurns(), 2);
    clock.tick(book, 0.0);
    EXPECT_EQ(clock.queuedTurns(), 2);
    for (double t = 0.25; t <= 1.0; t += 0.25) clock.tick(book, t);  // the first turn lands
    EXPECT_EQ(clock.queuedTurns(), 1);  // backward started as the first landed; forward waits for its leaf
    EXPECT_EQ(book.position(), 0);
    for (double t = 1.25; t <= 2.0; t += 0.25) clock.tick(book, t);  // backward lands, forward starts
    EXPECT_EQ(clock.queuedTurns(), 0);
    EXPECT_EQ(book.position(), 1);
    EXPECT_TRUE(book.animating());
}

TEST(BookClock, AtTheEndOfTheBookATurnIsRefusedAndLeftoverQueueIsDroppedWhenItSettles) {
    Book book = bookOf(2);  // one leaf: one forward turn is all there is
    BookClock clock;
    EXPECT_EQ(clock.requestTurn(book, TurnDirection::Backward, 0.0), TurnRequest::Refused);
    ASSERT_EQ(clock.requestTurn(book, TurnDirection::Forward, 0.0), TurnRequest::Started);
    EXPECT_EQ(clock.requestTurn(book, TurnDirection::Forward, 0.0), TurnRequest::Queued);  // may never start
    for (double t = 0.0; t <= 1.01; t += 0.25) clock.tick(book, t);
    EXPECT_FALSE(book.animating());
    EXPECT_EQ(clock.queuedTurns(), 0);
}

TEST(BookClock, TheQueueIsBounded) {
    Book book = bookOf(400);
    BookClock clock;
    clock.requestTurn(book, TurnDirection::Forward, 0.0);
    for (int i = 0; i < BookClock::kMaxQueuedTurns; ++i) {
        EXPECT_EQ(clock.requestTurn(book, TurnDirection::Backward, 0.0), TurnRequest::Queued);
    }
    EXPECT_EQ(clock.requestTurn(book, TurnDirection::Backward, 0.0), TurnRequest::Refused);
}

TEST(BookClock, RunningAlreadyKeepsItsLastTickAndANonFiniteTimeAdvancesNothing) {
    Book book = bookOf(8);
    BookClock clock;
    clock.requestTurn(book, TurnDirection::Forward, 0.0);
    clock.tick(book, 0.25);
    clock.run(0.4);  // asked to run mid-turn: the clock keeps counting from its last tick (0.25), not 0.4
    clock.tick(book, 0.5);
    clock.tick(book, 0.75);
    EXPECT_TRUE(book.animating());
    clock.tick(book, 1.0);
    EXPECT_FALSE(book.animating());
    BookClock other;
    Book second = bookOf(8);
    other.requestTurn(second, TurnDirection::Forward, std::nan(""));
    other.tick(second, 5.0);
    other.tick(second, 5.25);
    EXPECT_TRUE(second.animating());  // 0.25 s of a 1 s turn
}

TEST(BookClock, AStoppedClockShowsAnExactPoseAndReportsSettledWithoutAdvancing) {
    Book book = bookOf(8);
    BookClock clock;
    ASSERT_TRUE(book.startTurn(TurnDirection::Forward));
    book.setLatestTurnProgress(0.3);
    clock.stop();
    const int flags = clock.tick(book, 5.0);
    EXPECT_FALSE(flags & kTickMoving);
    EXPECT_TRUE(flags & kTickSettled);
    EXPECT_TRUE(book.animating());  // still posed at 0.3
    EXPECT_EQ(clock.frame().count, book.frame().count);
}

TEST(BookClock, AHeldLeafLyingStillNeitherMovesNorSettles) {
    Book book = bookOf(8);
    BookClock clock;
    ASSERT_TRUE(book.startHeldTurn(TurnDirection::Forward, false));
    clock.run(1.0);
    const int flags = clock.tick(book, 1.0);
    EXPECT_FALSE(flags & kTickMoving);
    EXPECT_FALSE(flags & kTickSettled);
}

TEST(BookClock, PagesChangedIsReportedOnTheFirstTickAndWhenTheDrawnPagesChangeOnly) {
    Book book = bookOf(8);
    BookClock clock;
    book.jumpTo(1);
    EXPECT_TRUE(clock.tick(book, 0.0) & kTickPagesChanged);
    EXPECT_FALSE(clock.tick(book, 0.1) & kTickPagesChanged);
    clock.requestTurn(book, TurnDirection::Forward, 0.15);
    EXPECT_TRUE(clock.tick(book, 0.2) & kTickPagesChanged);  // the turning leaf's back and the page under it
    EXPECT_FALSE(clock.tick(book, 0.3) & kTickPagesChanged);
}

TEST(BookClockMotion, ALeafsSpeedIntegratedOverItsTurnIsTheHalfTurnItMakes) {
    // A rigid leaf turns from rho 0 to pi: speed x dt summed over the ticks it is in flight in is pi,
    // less the first step (it counts from its second tick in flight) and the landing step, both tiny
    // at 1 ms ticks because the rigid turn eases in and out.
    Book book = hardBookOf(8);
    BookClock clock;
    const double step = 0.001;
    const std::vector<LeafMotion> motions = motionsOfATurn(book, clock, step);
    double turned = 0.0;
    for (const LeafMotion& m : motions) turned += m.speed * step;
    EXPECT_NEAR(turned, 3.14159265, 0.01);
    EXPECT_GT(peakSpeed(motions), 3.14159265);  // eased: faster than the average pi rad/s mid-turn
    for (const LeafMotion& m : motions) {
        if (m.speed > 0.0) EXPECT_TRUE(m.hard);
    }
}

TEST(BookClockMotion, ATurnTwiceAsLongPeaksAtHalfTheSpeedAndASoftLeafIsNotHard) {
    Book fast = hardBookOf(8, 0.5);
    Book slow = hardBookOf(8, 1.0);
    BookClock fastClock;
    BookClock slowClock;
    const double fastPeak = peakSpeed(motionsOfATurn(fast, fastClock, 0.001));
    const double slowPeak = peakSpeed(motionsOfATurn(slow, slowClock, 0.001));
    EXPECT_NEAR(fastPeak / slowPeak, 2.0, 0.02);

    Book soft = bookOf(8);
    BookClock softClock;
    const std::vector<LeafMotion> motions = motionsOfATurn(soft, softClock, 1.0 / 60.0);
    EXPECT_GT(peakSpeed(motions), 1.0);
    for (const LeafMotion& m : motions) EXPECT_FALSE(m.hard);
}

TEST(BookClockMotion, ALandingIsReportedOnceOnTheTickItLandsInWithItsHardness) {
    for (const bool hard : {false, true}) {
        Book book = hard ? hardBookOf(8) : bookOf(8);
        BookClock clock;
        const std::vector<LeafMotion> motions = motionsOfATurn(book, clock, 1.0 / 60.0);
        int landings = 0;
        for (size_t i = 0; i < motions.size(); ++i) {
            landings += motions[i].landings;
            if (motions[i].landings > 0) {
                EXPECT_EQ(i, motions.size() - 1) << "lands on the tick that settles";
                EXPECT_EQ(motions[i].landedHard, hard);
                EXPECT_EQ(motions[i].speed, 0.0);  // nothing left in flight
            }
        }
        EXPECT_EQ(landings, 1);
    }
}

TEST(BookClockMotion, AJumpMidTurnIsNoLandingAndARestingBookHasNoSpeed) {
    Book book = bookOf(8);
    BookClock clock;
    clock.requestTurn(book, TurnDirection::Forward, 0.0);
    clock.tick(book, 0.0);
    clock.tick(book, 0.1);
    EXPECT_GT(clock.motion().speed, 0.0);
    book.jumpTo(3);
    clock.tick(book, 0.2);
    EXPECT_EQ(clock.motion().landings, 0);
    EXPECT_EQ(clock.motion().speed, 0.0);
    clock.tick(book, 0.3);
    EXPECT_EQ(clock.motion().speed, 0.0);
}

TEST(BookClockMotion, AHeldLeafMovedBetweenTicksHasTheSpeedOfItsPoseOverTheTimeBetweenThem) {
    // A pointer moves the held leaf: the tick after it measures the pose's step over the time since the
    // previous tick, whether the clock ran between them or not (a slow drag lies still between moves).
    Book book = bookOf(8);
    BookClock clock;
    ASSERT_TRUE(book.startHeldTurn(TurnDirection::Forward, false));
    CurlParams pose = book.heldPose();
    pose.rho = 0.5;
    book.setHeldPose(pose);
    clock.run(1.0);
    clock.tick(book, 1.0);
    pose.rho = 1.0;
    book.setHeldPose(pose);
    clock.run(1.2);
    clock.tick(book, 1.25);
    EXPECT_NEAR(clock.motion().speed, 0.5 / 0.25, 1e-9);  // 0.5 rad over the 0.25 s since the last tick
    EXPECT_EQ(clock.motion().landings, 0);
    clock.tick(book, 1.5);  // lying still
    EXPECT_EQ(clock.motion().speed, 0.0);
}

TEST(PagesOnScreen, RestingLeavesShowOneSideTurningLeavesBothAndBlanksNone) {
    Book book = bookOf(8);
    book.jumpTo(2);  // pages 3 and 4 open
    EXPECT_EQ(pagesOf(pagesOnScreen(book.frame())), (std::vector<int>{3, 4}));
    ASSERT_TRUE(book.startTurn(TurnDirection::Forward));  // leaf 2 (pages 4, 5) lifts; page 6 lies under it
    const std::vector<int> turning = pagesOf(pagesOnScreen(book.frame()));
    for (int page : {3, 4, 5, 6}) EXPECT_NE(std::find(turning.begin(), turning.end(), page), turning.end()) << page;
    EXPECT_EQ(turning.size(), 4u);

    Book odd = bookOf(3);  // the last leaf has a blank back
    odd.jumpTo(odd.lastPosition());
    for (int page : pagesOf(pagesOnScreen(odd.frame()))) EXPECT_GE(page, 0);
    EXPECT_EQ(pagesOf(pagesOnScreen(bookOf(0).frame())), std::vector<int>{});
}

}  // namespace
