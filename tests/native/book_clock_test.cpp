// Native (GoogleTest via CTest) tests of the frame clock: capped steps, turns queued behind a leaf in
// flight and started in order, the flags a tick reports, and the pages a frame shows.
#include "book_clock.hpp"

#include <gtest/gtest.h>

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
