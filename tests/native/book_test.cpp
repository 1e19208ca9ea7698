// Native (GoogleTest via CTest) tests of the book model: which leaves a frame draws and in what pose,
// the turn state machine, and the placement tables that put every page in the world reading upright.
#include "test_support.hpp"
#include "book.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "cone_deform.hpp"
#include "curl_schedule.hpp"
#include "leaf_placement.hpp"

namespace {

using conecurl::Binding;
using conecurl::Book;
using conecurl::BookConfig;
using conecurl::BookFrame;
using conecurl::curlAt;
using conecurl::CurlParams;
using conecurl::CurlSchedule;
using conecurl::Display;
using conecurl::kMaxLeafDraws;
using conecurl::kMaxTurnsInFlight;
using conecurl::kNoPage;
using conecurl::LeafDraw;
using conecurl::LeafPlacement;
using conecurl::leafPointToWorld;
using conecurl::placeLeaf;
using conecurl::rigidTurnAt;
using conecurl::sanitize;
using conecurl::TurnDirection;
using conecurl::ViewFrame;
using conecurl::viewFrameFor;
using glm::dmat3;
using glm::dvec2;
using glm::dvec3;
using glm::dvec4;

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr TurnDirection kForward = TurnDirection::Forward;
constexpr TurnDirection kBackward = TurnDirection::Backward;
// Width and height differ from the defaults and from each other, so a swapped or dropped one shows.
constexpr double kW = 0.7;
constexpr double kH = 1.1;

const Binding kBindings[] = {Binding::Left, Binding::Right, Binding::Top};

const char* name(Binding b) {
    switch (b) {
        case Binding::Left: return "Left";
        case Binding::Right: return "Right";
        case Binding::Top: return "Top";
    }
    return "?";
}

const char* name(Display d) { return d == Display::Double ? "Double" : "Single"; }

Book makeBook(int pages, Display display = Display::Double, double turnSeconds = 1.0,
              std::vector<bool> hardPages = {}) {
    BookConfig config;
    config.pageCount = pages;
    config.display = display;
    config.pageWidth = kW;
    config.pageHeight = kH;
    config.turnSeconds = turnSeconds;
    config.hardPages = std::move(hardPages);
    return Book(config);
}

std::string str(const CurlParams& c) {
    std::ostringstream os;
    os.precision(17);
    os << "{theta " << c.theta << ", apexY " << c.apexY << ", rho " << c.rho << "}";
    return os.str();
}

std::string str(const LeafDraw& d) {
    std::ostringstream os;
    os << "leaf " << d.leaf << " (pages " << d.frontPage << "/" << d.backPage << ") "
       << (d.resting ? "resting" : "flying") << (d.mirrored ? " mirrored" : "") << (d.hard ? " hard" : "")
       << " " << str(d.curl);
    return os.str();
}

std::string str(const BookFrame& f) {
    std::ostringstream os;
    os << f.count << " draw(s):";
    for (int i = 0; i < f.count; ++i) os << "\n    [" << i << "] " << str(f.leaves[i]);
    return os.str();
}

bool sameCurl(const CurlParams& a, const CurlParams& b) {
    return a.theta == b.theta && a.apexY == b.apexY && a.rho == b.rho;
}

bool sameDraw(const LeafDraw& a, const LeafDraw& b) {
    return a.leaf == b.leaf && a.frontPage == b.frontPage && a.backPage == b.backPage && sameCurl(a.curl, b.curl) &&
           a.mirrored == b.mirrored && a.hard == b.hard && a.resting == b.resting;
}

bool sameFrame(const BookFrame& a, const BookFrame& b) {
    if (a.count != b.count) return false;
    for (int i = 0; i < a.count; ++i)
        if (!sameDraw(a.leaves[i], b.leaves[i])) return false;
    return true;
}

std::vector<LeafDraw> flying(const BookFrame& f) {
    std::vector<LeafDraw> out;
    for (int i = 0; i < f.count; ++i)
        if (!f.leaves[i].resting) out.push_back(f.leaves[i]);
    return out;
}

std::vector<LeafDraw> resting(const BookFrame& f) {
    std::vector<LeafDraw> out;
    for (int i = 0; i < f.count; ++i)
        if (f.leaves[i].resting) out.push_back(f.leaves[i]);
    return out;
}

// The pose of a flat leaf at rest: rho 0 unturned, pi turned.
CurlParams flatCurl(bool turned) { return CurlParams{kPi / 2.0, -15.0 * kH, turned ? kPi : 0.0}; }

// What a resting draw must be, independently of Book's helpers.
struct RestingLeaf {
    int leaf;
    int front;
    int back;
    bool turned;
};

// The frame at rest must hold exactly these resting leaves (turned first), flat, none flying.
void expectRestingFrame(const Book& book, const std::vector<RestingLeaf>& expected, const std::string& where) {
    const BookFrame f = book.frame();
    ASSERT_EQ(f.count, static_cast<int>(expected.size())) << where << "\n  frame: " << str(f);
    for (size_t i = 0; i < expected.size(); ++i) {
        const LeafDraw& d = f.leaves[i];
        const RestingLeaf& e = expected[i];
        const std::string ctx = where + "\n  draw " + std::to_string(i) + ": " + str(d);
        EXPECT_EQ(d.leaf, e.leaf) << ctx;
        EXPECT_EQ(d.frontPage, e.front) << ctx;
        EXPECT_EQ(d.backPage, e.back) << ctx;
        EXPECT_TRUE(d.resting) << ctx;
        EXPECT_FALSE(d.mirrored) << ctx;
        EXPECT_EQ(d.curl.rho, e.turned ? kPi : 0.0) << ctx << " (rho 0: unturned, pi: turned)";
        EXPECT_EQ(d.curl.theta, CurlSchedule{}.thetaRest) << ctx << " (resting leaves lie flat)";
        EXPECT_EQ(d.curl.apexY, CurlSchedule{}.apexRest * kH) << ctx;
    }
}

// Every frame, whatever is in flight: each leaf once, resting draws first, at most one resting leaf
// per side (turned below the position, unturned at or above it), within the fixed draw budget.
void expectWellFormedFrame(const Book& book, const std::string& where) {
    const BookFrame f = book.frame();
    const std::string ctx = where + "\n  position " + std::to_string(book.position()) + ", frame: " + str(f);
    ASSERT_LE(f.count, kMaxLeafDraws) << ctx;
    std::set<int> leaves;
    bool seenFlying = false;
    int restingTurned = 0;
    int restingUnturned = 0;
    for (int i = 0; i < f.count; ++i) {
        const LeafDraw& d = f.leaves[i];
        EXPECT_TRUE(leaves.insert(d.leaf).second) << "leaf " << d.leaf << " drawn twice. " << ctx;
        EXPECT_TRUE(d.leaf >= 0 && d.leaf < book.leafCount()) << ctx;
        if (d.resting) {
            EXPECT_FALSE(seenFlying) << "a resting draw after a flying one: " << ctx;
            if (d.curl.rho == kPi) {
                ++restingTurned;
                EXPECT_LT(d.leaf, book.position()) << ctx;
            } else {
                ++restingUnturned;
                EXPECT_EQ(d.curl.rho, 0.0) << ctx;
                EXPECT_GE(d.leaf, book.position()) << ctx;
            }
        } else {
            seenFlying = true;
        }
        if (book.config().display == Display::Double) {
            EXPECT_EQ(d.frontPage, 2 * d.leaf < book.config().pageCount ? 2 * d.leaf : kNoPage) << ctx;
            EXPECT_EQ(d.backPage, 2 * d.leaf + 1 < book.config().pageCount ? 2 * d.leaf + 1 : kNoPage) << ctx;
        }
    }
    EXPECT_LE(restingTurned, 1) << ctx;
    EXPECT_LE(restingUnturned, 1) << ctx;
    EXPECT_LE(static_cast<int>(flying(f).size()), kMaxTurnsInFlight) << ctx;
    EXPECT_EQ(book.animating(), !flying(f).empty()) << ctx;
}

// =================================================================================================
// Book: double display at rest.

// Leaf i carries pages 2i and 2i+1; position s rests leaf s-1 turned (showing page 2s-1) and leaf s
// unturned (showing page 2s); a side with no leaf draws nothing.
TEST(Book, DoubleDisplayAtRestDrawsTheTopLeafOfEachStackWithItsTwoPages) {
    for (int n : {1, 2, 5, 6, 40}) {
        Book book = makeBook(n);
        const int leaves = (n + 1) / 2;
        ASSERT_EQ(book.leafCount(), leaves) << "pageCount " << n;
        ASSERT_EQ(book.lastPosition(), leaves) << "pageCount " << n;
        ASSERT_EQ(book.position(), 0) << "pageCount " << n << ": a new book opens at position 0";
        for (int s = 0; s <= leaves; ++s) {
            book.jumpTo(s);
            ASSERT_EQ(book.position(), s);
            const std::string where = "pageCount " + std::to_string(n) + ", position " + std::to_string(s);
            std::vector<RestingLeaf> expected;
            auto page = [&](int p) { return p < n ? p : kNoPage; };
            if (s > 0) expected.push_back({s - 1, 2 * (s - 1), page(2 * s - 1), true});
            if (s < leaves) expected.push_back({s, 2 * s, page(2 * s + 1), false});
            expectRestingFrame(book, expected, where);
            EXPECT_FALSE(book.animating()) << where;
            // First visible page: the turned side's 2s-1, else the unturned side's 2s.
            if (s > 0 && 2 * s - 1 < n) {
                EXPECT_EQ(book.firstVisiblePage(), 2 * s - 1) << where;
            } else if (2 * s < n) {
                EXPECT_EQ(book.firstVisiblePage(), 2 * s) << where;
            }
            // (the spread where neither page exists has its own test below)
        }
    }
}

TEST(Book, DoubleDisplayPositionZeroShowsPageZeroAloneOnTheUnturnedSide) {
    const Book book = makeBook(40);
    expectRestingFrame(book, {{0, 0, 1, false}}, "pageCount 40, position 0");
    EXPECT_EQ(book.firstVisiblePage(), 0);
}

TEST(Book, DoubleDisplayOddBookEndsWithALeafWhoseBackIsBlank) {
    Book book = makeBook(5);
    book.jumpTo(2);  // pages 3 | 4: leaf 2 carries page 4 and blank paper
    expectRestingFrame(book, {{1, 2, 3, true}, {2, 4, kNoPage, false}}, "pageCount 5, position 2");
    EXPECT_EQ(book.firstVisiblePage(), 3);
    book.jumpTo(3);  // the blank back of leaf 2 | nothing
    expectRestingFrame(book, {{2, 4, kNoPage, true}}, "pageCount 5, position 3");
}

// The header promises "first visible page at the settled position, or kNoPage for none". At the last
// spread of an odd book (and position 1 of a one-page book) only the blank back of the last leaf shows.
// At the last spread of an odd book only a blank back shows; firstVisiblePage() then names the last
// page (face down under it) so "page N of N" labels and jumps back to it stay meaningful.
TEST(Book, FirstVisiblePageAtABlankLastSpreadIsTheLastPage) {
    Book five = makeBook(5);
    five.jumpTo(3);
    EXPECT_EQ(five.firstVisiblePage(), 4) << "pageCount 5, position 3";
    EXPECT_EQ(five.positionOfPage(five.firstVisiblePage()), 2) << "its page maps to the spread that shows it";
    Book one = makeBook(1);
    one.jumpTo(1);
    EXPECT_EQ(one.firstVisiblePage(), 0) << "pageCount 1, position 1";
}

// =================================================================================================
// Book: single display.

TEST(Book, SingleDisplayLeafIsAPageAndOnlyTheUnturnedPageIsDrawn) {
    for (int n : {1, 2, 5, 40}) {
        Book book = makeBook(n, Display::Single);
        ASSERT_EQ(book.leafCount(), n) << "pageCount " << n;
        ASSERT_EQ(book.lastPosition(), n - 1) << "pageCount " << n;
        for (int s = 0; s < n; ++s) {
            book.jumpTo(s);
            const std::string where = "single, pageCount " + std::to_string(n) + ", position " + std::to_string(s);
            // The turned page s-1 lies outside the view: not drawn.
            expectRestingFrame(book, {{s, s, kNoPage, false}}, where);
            EXPECT_EQ(book.firstVisiblePage(), s) << where;
        }
        book.jumpTo(n + 3);
        EXPECT_EQ(book.position(), n - 1) << "single display stops on the last page";
    }
}

// =================================================================================================
// Book: starting turns.

TEST(Book, ForwardTurnFliesTheTopUnturnedLeafFromTheSchedulesFirstPose) {
    BookConfig config;
    config.pageCount = 40;
    config.pageWidth = kW;
    config.pageHeight = kH;
    config.schedule.apexRest = -12.0;  // a non-default schedule: the book must use its own
    config.schedule.apexPhase1 = -3.0;
    Book book(config);
    book.jumpTo(3);  // pages 5 | 6
    ASSERT_TRUE(book.startTurn(kForward));
    EXPECT_EQ(book.position(), 4) << "the position is where the book settles";
    EXPECT_TRUE(book.animating());

    const BookFrame f = book.frame();
    ASSERT_EQ(f.count, 3) << str(f);
    const std::vector<LeafDraw> rest = resting(f);
    const std::vector<LeafDraw> fly = flying(f);
    ASSERT_EQ(rest.size(), 2u) << str(f);
    ASSERT_EQ(fly.size(), 1u) << str(f);
    EXPECT_EQ(rest[0].leaf, 2) << "the top turned leaf stays put: " << str(f);
    EXPECT_EQ(rest[0].curl.rho, kPi) << str(f);
    EXPECT_EQ(rest[1].leaf, 4) << "the leaf beneath the flying one rests unturned: " << str(f);
    EXPECT_EQ(rest[1].curl.rho, 0.0) << str(f);
    EXPECT_EQ(fly[0].leaf, 3) << str(f);
    EXPECT_EQ(fly[0].frontPage, 6) << str(f);
    EXPECT_EQ(fly[0].backPage, 7) << str(f);
    EXPECT_FALSE(fly[0].mirrored) << str(f);
    EXPECT_FALSE(fly[0].hard) << str(f);
    const CurlParams want = sanitize(curlAt(0.0, config.schedule, kH));
    EXPECT_TRUE(sameCurl(fly[0].curl, want)) << "got " << str(fly[0].curl) << ", want " << str(want);
    EXPECT_EQ(fly[0].curl.apexY, -12.0 * kH);
    // Later frames follow the book's schedule, not the default one.
    book.setLatestTurnProgress(0.3);
    EXPECT_TRUE(sameCurl(flying(book.frame())[0].curl, sanitize(curlAt(0.3, config.schedule, kH))))
        << str(book.frame());
}

TEST(Book, BackwardTurnFliesTheTopTurnedLeafMirrored) {
    Book book = makeBook(40);
    book.jumpTo(3);  // pages 5 | 6
    ASSERT_TRUE(book.startTurn(kBackward));
    EXPECT_EQ(book.position(), 2);
    const BookFrame f = book.frame();
    const std::vector<LeafDraw> rest = resting(f);
    const std::vector<LeafDraw> fly = flying(f);
    ASSERT_EQ(rest.size(), 2u) << str(f);
    ASSERT_EQ(fly.size(), 1u) << str(f);
    EXPECT_EQ(rest[0].leaf, 1) << str(f);
    EXPECT_EQ(rest[0].curl.rho, kPi) << str(f);
    EXPECT_EQ(rest[1].leaf, 3) << str(f);
    EXPECT_EQ(rest[1].curl.rho, 0.0) << str(f);
    EXPECT_EQ(fly[0].leaf, 2) << str(f);
    EXPECT_EQ(fly[0].frontPage, 4) << str(f);
    EXPECT_EQ(fly[0].backPage, 5) << str(f);
    EXPECT_TRUE(fly[0].mirrored) << str(f);
    EXPECT_TRUE(sameCurl(fly[0].curl, sanitize(curlAt(0.0, CurlSchedule{}, kH)))) << str(f);
}

TEST(Book, SingleDisplayTurnsFlyOnePageAndRestOnlyTheUnturnedOne) {
    Book book = makeBook(10, Display::Single);
    book.jumpTo(4);
    ASSERT_TRUE(book.startTurn(kForward));
    EXPECT_EQ(book.position(), 5);
    BookFrame f = book.frame();
    ASSERT_EQ(f.count, 2) << str(f);
    EXPECT_TRUE(f.leaves[0].resting && f.leaves[0].leaf == 5 && f.leaves[0].curl.rho == 0.0) << str(f);
    EXPECT_TRUE(!f.leaves[1].resting && f.leaves[1].leaf == 4 && f.leaves[1].frontPage == 4 &&
                f.leaves[1].backPage == kNoPage && !f.leaves[1].mirrored)
        << str(f);

    book.jumpTo(4);
    ASSERT_TRUE(book.startTurn(kBackward));
    EXPECT_EQ(book.position(), 3);
    f = book.frame();
    ASSERT_EQ(f.count, 2) << str(f);
    EXPECT_TRUE(f.leaves[0].resting && f.leaves[0].leaf == 4 && f.leaves[0].curl.rho == 0.0) << str(f);
    EXPECT_TRUE(!f.leaves[1].resting && f.leaves[1].leaf == 3 && f.leaves[1].frontPage == 3 && f.leaves[1].mirrored)
        << str(f);
}

TEST(Book, StartTurnIsRefusedAtTheEndsAndChangesNothing) {
    for (Display display : {Display::Double, Display::Single}) {
        Book book = makeBook(7, display);
        const std::string d = name(display);
        BookFrame before = book.frame();
        EXPECT_FALSE(book.startTurn(kBackward)) << d << ": backward at position 0";
        EXPECT_EQ(book.position(), 0) << d;
        EXPECT_FALSE(book.animating()) << d;
        EXPECT_TRUE(sameFrame(book.frame(), before)) << d << ": " << str(book.frame());

        book.jumpTo(book.lastPosition());
        before = book.frame();
        EXPECT_FALSE(book.startTurn(kForward)) << d << ": forward at the last position";
        EXPECT_EQ(book.position(), book.lastPosition()) << d;
        EXPECT_FALSE(book.animating()) << d;
        EXPECT_TRUE(sameFrame(book.frame(), before)) << d << ": " << str(book.frame());

        // A forward turn onto the last position leaves no room for another.
        book.jumpTo(book.lastPosition() - 1);
        ASSERT_TRUE(book.startTurn(kForward)) << d;
        before = book.frame();
        EXPECT_FALSE(book.startTurn(kForward)) << d << ": forward while the last turn is landing";
        EXPECT_TRUE(sameFrame(book.frame(), before)) << d << ": " << str(book.frame());
    }
}

TEST(Book, StartTurnIsRefusedForALeafAlreadyInFlight) {
    for (Display display : {Display::Double, Display::Single}) {
        Book book = makeBook(20, display);
        book.jumpTo(4);
        ASSERT_TRUE(book.startTurn(kForward));  // leaf 4; settles at 5
        book.setLatestTurnProgress(0.4);
        const BookFrame before = book.frame();
        // Backward at 5 would take leaf 4, which is still turning.
        EXPECT_FALSE(book.startTurn(kBackward)) << name(display);
        EXPECT_EQ(book.position(), 5) << name(display);
        EXPECT_TRUE(sameFrame(book.frame(), before)) << name(display) << ": " << str(book.frame());

        book.jumpTo(4);
        ASSERT_TRUE(book.startTurn(kBackward));  // leaf 3; settles at 3
        EXPECT_FALSE(book.startTurn(kForward)) << name(display) << ": forward at 3 would take leaf 3 again";
        EXPECT_EQ(book.position(), 3) << name(display);
    }
}

TEST(Book, StartTurnIsRefusedOnceMaxTurnsAreInFlight) {
    Book book = makeBook(40);
    book.jumpTo(3);  // a turned leaf to rest on the left as well
    for (int i = 0; i < kMaxTurnsInFlight; ++i) ASSERT_TRUE(book.startTurn(kForward)) << "turn " << i;
    EXPECT_EQ(book.position(), 3 + kMaxTurnsInFlight);
    const BookFrame before = book.frame();
    EXPECT_EQ(before.count, kMaxLeafDraws) << "all turns plus both resting leaves: " << str(before);
    EXPECT_FALSE(book.startTurn(kForward)) << "turn " << kMaxTurnsInFlight;
    EXPECT_FALSE(book.startTurn(kBackward)) << "backward would also be a new turn";
    EXPECT_EQ(book.position(), 3 + kMaxTurnsInFlight);
    EXPECT_TRUE(sameFrame(book.frame(), before)) << str(book.frame());
    expectWellFormedFrame(book, "six turns in flight");
    // Once one lands there is room again.
    book.setLatestTurnProgress(1.0);
    book.advance(1e-3);
    EXPECT_TRUE(book.startTurn(kForward)) << "five in flight after one landed";
}

// =================================================================================================
// Book: progress, hard leaves, the rigid turn.

TEST(Book, LatestTurnProgressGivesTheScheduleExactlyForSoftLeaves) {
    Book book = makeBook(40);
    book.jumpTo(5);
    ASSERT_TRUE(book.startTurn(kForward));  // leaf 5
    book.setLatestTurnProgress(0.2);
    ASSERT_TRUE(book.startTurn(kForward));  // leaf 6, the latest
    for (int i = 0; i <= 100; ++i) {
        const double p = i / 100.0;
        book.setLatestTurnProgress(p);
        const std::vector<LeafDraw> fly = flying(book.frame());
        ASSERT_EQ(fly.size(), 2u);
        const CurlParams want = sanitize(curlAt(p, CurlSchedule{}, kH));
        EXPECT_EQ(fly[1].leaf, 6);
        EXPECT_TRUE(sameCurl(fly[1].curl, want)) << "p " << p << ": got " << str(fly[1].curl) << ", want " << str(want);
        EXPECT_TRUE(sameCurl(fly[0].curl, sanitize(curlAt(0.2, CurlSchedule{}, kH))))
            << "only the latest turn moves; leaf 5 is at " << str(fly[0].curl);
    }
    // Out of range and NaN progress are clamped / rest at 0.
    const std::pair<double, double> cases[] = {{-0.5, 0.0}, {1.5, 1.0}, {kNaN, 0.0}};
    for (auto [in, clamped] : cases) {
        book.setLatestTurnProgress(in);
        EXPECT_TRUE(sameCurl(flying(book.frame())[1].curl, sanitize(curlAt(clamped, CurlSchedule{}, kH))))
            << "progress " << in << " should act as " << clamped << ": " << str(book.frame());
    }
    // With nothing in flight it does nothing.
    Book idle = makeBook(40);
    const BookFrame before = idle.frame();
    idle.setLatestTurnProgress(0.5);
    EXPECT_TRUE(sameFrame(idle.frame(), before));
}

TEST(Book, ALeafIsHardIfEitherOfItsPagesIsHard) {
    // Double: page 0 makes leaf 0 hard (front); page 3 makes leaf 1 hard (back); pages past the list are soft.
    const Book dbl = makeBook(10, Display::Double, 1.0, {true, false, false, true});
    EXPECT_TRUE(dbl.isHardLeaf(0));
    EXPECT_TRUE(dbl.isHardLeaf(1));
    for (int leaf = 2; leaf < 5; ++leaf) EXPECT_FALSE(dbl.isHardLeaf(leaf)) << "leaf " << leaf;
    // Single: leaf = page.
    const Book single = makeBook(4, Display::Single, 1.0, {false, true});
    EXPECT_FALSE(single.isHardLeaf(0));
    EXPECT_TRUE(single.isHardLeaf(1));
    EXPECT_FALSE(single.isHardLeaf(2));
    // The last leaf of an odd book: its missing back is not hard by accident.
    const Book odd = makeBook(5, Display::Double, 1.0, {false, false, false, false, false, true});
    EXPECT_FALSE(odd.isHardLeaf(2)) << "page 5 does not exist in a 5-page book";
    // Resting draws carry the flag too.
    const BookFrame f = dbl.frame();
    ASSERT_EQ(f.count, 1);
    EXPECT_TRUE(f.leaves[0].hard) << str(f);
}

TEST(Book, HardLeavesTurnRigidlyAndSoftLeavesCurl) {
    Book book = makeBook(10, Display::Double, 1.0, {true, false, false, true});
    for (int leaf = 0; leaf < 3; ++leaf) {
        book.jumpTo(leaf);
        ASSERT_TRUE(book.startTurn(kForward));
        const bool hard = leaf < 2;
        for (double p : {0.0, 0.1, 0.25, 0.5, 0.77, 1.0}) {
            book.setLatestTurnProgress(p);
            const std::vector<LeafDraw> fly = flying(book.frame());
            ASSERT_EQ(fly.size(), 1u);
            EXPECT_EQ(fly[0].hard, hard) << "leaf " << leaf;
            const CurlParams want = hard ? rigidTurnAt(p, kH) : sanitize(curlAt(p, CurlSchedule{}, kH));
            EXPECT_TRUE(sameCurl(fly[0].curl, want))
                << "leaf " << leaf << (hard ? " (hard)" : " (soft)") << ", p " << p << ": got " << str(fly[0].curl)
                << ", want " << str(want);
        }
    }
    // Backward turns of hard leaves are rigid too.
    book.jumpTo(2);
    ASSERT_TRUE(book.startTurn(kBackward));  // leaf 1, hard by its back page
    book.setLatestTurnProgress(0.6);
    const std::vector<LeafDraw> fly = flying(book.frame());
    ASSERT_EQ(fly.size(), 1u);
    EXPECT_TRUE(fly[0].mirrored && fly[0].hard) << str(fly[0]);
    EXPECT_TRUE(sameCurl(fly[0].curl, rigidTurnAt(0.6, kH))) << str(fly[0]);
}

TEST(Book, RigidTurnIsFlatAndEasesFromZeroToPiWithZeroSlopeAtBothEnds) {
    const int n = 1000;
    double prev = -1.0;
    double maxSlope = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double p = static_cast<double>(i) / n;
        const CurlParams c = rigidTurnAt(p, kH);
        EXPECT_EQ(c.theta, kPi / 2.0) << "p " << p << ": a hard leaf stays flat";
        EXPECT_EQ(c.apexY, -15.0 * kH) << "p " << p;
        EXPECT_GT(c.rho, prev) << "rho must increase strictly; p " << p;
        prev = c.rho;
        if (i > 0) maxSlope = std::max(maxSlope, (c.rho - rigidTurnAt((i - 1.0) / n, kH).rho) * n);
    }
    EXPECT_EQ(rigidTurnAt(0.0, kH).rho, 0.0);
    EXPECT_NEAR(rigidTurnAt(1.0, kH).rho, kPi, 1e-15);
    // Eased: the slope at both ends vanishes (pi^3 / 4 * eps here) while mid-turn it is pi^2 / 2.
    const double eps = 1e-5;
    const double startSlope = (rigidTurnAt(eps, kH).rho - rigidTurnAt(0.0, kH).rho) / eps;
    const double endSlope = (rigidTurnAt(1.0, kH).rho - rigidTurnAt(1.0 - eps, kH).rho) / eps;
    EXPECT_LT(std::abs(startSlope), 1e-4) << "slope at p = 0";
    EXPECT_LT(std::abs(endSlope), 1e-4) << "slope at p = 1";
    EXPECT_NEAR(maxSlope, kPi * kPi / 2.0, 1e-3) << "the largest slope, mid-turn";
    // NaN rests at 0; out of range clamps.
    EXPECT_TRUE(sameCurl(rigidTurnAt(kNaN, kH), rigidTurnAt(0.0, kH))) << str(rigidTurnAt(kNaN, kH));
    EXPECT_TRUE(sameCurl(rigidTurnAt(-3.0, kH), rigidTurnAt(0.0, kH)));
    EXPECT_TRUE(sameCurl(rigidTurnAt(7.0, kH), rigidTurnAt(1.0, kH)));
}

// =================================================================================================
// Book: time.

TEST(Book, AdvanceMovesProgressBySecondsOverTurnSecondsAndLandsTheTurnAtOne) {
    Book book = makeBook(40, Display::Double, 2.0);
    book.jumpTo(3);
    ASSERT_TRUE(book.startTurn(kForward));
    auto curlNow = [&] {
        const std::vector<LeafDraw> fly = flying(book.frame());
        EXPECT_EQ(fly.size(), 1u);
        return fly.empty() ? CurlParams{} : fly[0].curl;
    };
    EXPECT_TRUE(book.advance(0.5));  // 0.5 s of 2 s
    EXPECT_TRUE(sameCurl(curlNow(), sanitize(curlAt(0.25, CurlSchedule{}, kH)))) << str(book.frame());
    EXPECT_TRUE(book.advance(1.0));
    EXPECT_TRUE(sameCurl(curlNow(), sanitize(curlAt(0.75, CurlSchedule{}, kH)))) << str(book.frame());
    EXPECT_FALSE(book.advance(0.5)) << "progress reaches exactly 1: the turn lands";
    EXPECT_FALSE(book.animating());
    EXPECT_EQ(book.position(), 4);
    expectRestingFrame(book, {{3, 6, 7, true}, {4, 8, 9, false}}, "after the turn landed");

    // A long step lands every turn in flight at once.
    ASSERT_TRUE(book.startTurn(kForward));
    ASSERT_TRUE(book.startTurn(kForward));
    EXPECT_FALSE(book.advance(10.0));
    EXPECT_EQ(book.position(), 6);
    expectRestingFrame(book, {{5, 10, 11, true}, {6, 12, 13, false}}, "after a long step");
}

TEST(Book, AdvanceByZeroNegativeOrNaNChangesNothing) {
    Book book = makeBook(40);
    book.jumpTo(3);
    ASSERT_TRUE(book.startTurn(kForward));
    book.setLatestTurnProgress(0.3);
    const BookFrame before = book.frame();
    for (double s : {0.0, -0.0, -0.5, -1e9, kNaN, -std::numeric_limits<double>::infinity()}) {
        EXPECT_TRUE(book.advance(s)) << "advance(" << s << ") still reports the turn in flight";
        EXPECT_TRUE(sameFrame(book.frame(), before)) << "advance(" << s << "): " << str(book.frame());
        EXPECT_EQ(book.position(), 4);
    }
    Book idle = makeBook(40);
    EXPECT_FALSE(idle.advance(kNaN));
    EXPECT_FALSE(idle.advance(1.0));
}

struct Clicks {
    std::vector<bool> accepted;
    int maxInFlight = 0;
};

// `clicks` forward clicks `gap` seconds apart, the clock advancing between them; every frame checked.
Clicks clickForward(Book& book, int clicks, double gap) {
    Clicks out;
    for (int k = 0; k < clicks; ++k) {
        out.accepted.push_back(book.startTurn(kForward));
        const int inFlight = static_cast<int>(flying(book.frame()).size());
        out.maxInFlight = std::max(out.maxInFlight, inFlight);
        expectWellFormedFrame(book, "after click " + std::to_string(k));
        if (k + 1 < clicks) book.advance(gap);
    }
    return out;
}

std::string str(const std::vector<bool>& v) {
    std::string s;
    for (bool b : v) s += b ? 'Y' : 'n';
    return s;
}

// Settles the book in 100 ms steps; returns how many steps it took (or -1 if it never settles).
int settle(Book& book) {
    for (int step = 1; step <= 100; ++step) {
        book.advance(0.1);
        expectWellFormedFrame(book, "settling, step " + std::to_string(step));
        if (!book.animating()) return step;
    }
    return -1;
}

TEST(Book, TenRapidClicksFiftyMsApartStartSixTurnsAndSettleSixLeavesOn) {
    // With turns of 1 s, clicks at 0, 50, ..., 450 ms: no turn has landed by the last click, so the
    // first six start and the last four find kMaxTurnsInFlight turns in flight.
    Book book = makeBook(40, Display::Double, 1.0);
    const Clicks c = clickForward(book, 10, 0.05);
    EXPECT_EQ(str(c.accepted), "YYYYYYnnnn");
    EXPECT_EQ(c.maxInFlight, kMaxTurnsInFlight);
    EXPECT_EQ(book.position(), 6);
    EXPECT_GT(settle(book), 0) << "never settled";
    EXPECT_FALSE(book.animating());
    EXPECT_EQ(book.position(), 6);
    expectRestingFrame(book, {{5, 10, 11, true}, {6, 12, 13, false}}, "settled after ten rapid clicks");
}

TEST(Book, ClicksOneFiftyMsApartRefuseOnlyWhileSixTurnsAreInFlight) {
    // Clicks at 0, 0.15, ..., 1.35 s with 1 s turns: the turn started by click j lands before click j+7
    // (1.05 s later) but not before click j+6 (0.9 s). Click 6 finds six in flight; clicks 7, 8, 9 each
    // find one just landed.
    Book book = makeBook(40, Display::Double, 1.0);
    const Clicks c = clickForward(book, 10, 0.15);
    EXPECT_EQ(str(c.accepted), "YYYYYYnYYY");
    EXPECT_EQ(c.maxInFlight, kMaxTurnsInFlight);
    EXPECT_GT(settle(book), 0) << "never settled";
    EXPECT_EQ(book.position(), 9);
    expectRestingFrame(book, {{8, 16, 17, true}, {9, 18, 19, false}}, "settled");
}

TEST(Book, RapidClicksInAShortBookStopAtTheLastPosition) {
    // Six pages: three leaves, last position 3. Clicks 3..9 are refused by the end of the book.
    for (Display display : {Display::Double, Display::Single}) {
        Book book = makeBook(6, display, 1.0);
        const Clicks c = clickForward(book, 10, 0.05);
        const int last = book.lastPosition();
        EXPECT_EQ(last, display == Display::Double ? 3 : 5);
        EXPECT_EQ(str(c.accepted), std::string(last, 'Y') + std::string(10 - last, 'n')) << name(display);
        EXPECT_GT(settle(book), 0) << name(display);
        EXPECT_EQ(book.position(), last) << name(display);
        EXPECT_FALSE(book.startTurn(kForward)) << name(display);
    }
}

// =================================================================================================
// Book: several turns in flight.

TEST(Book, WithSeveralTurnsInFlightEachLeafIsDrawnExactlyOnce) {
    // A deterministic walk of clicks both ways, scrubbing and time steps; every frame is checked.
    for (Display display : {Display::Double, Display::Single}) {
        Book book = makeBook(23, display, 0.7);
        book.jumpTo(5);
        unsigned state = 12345u;
        auto next = [&] { return (state = state * 1103515245u + 12345u) >> 16; };
        int starts = 0;
        for (int step = 0; step < 600; ++step) {
            const unsigned r = next() % 10;
            if (r < 4) starts += book.startTurn(kForward);
            else if (r < 6) starts += book.startTurn(kBackward);
            else if (r < 7) book.setLatestTurnProgress((next() % 1001) / 1000.0);
            else book.advance((next() % 200) / 1000.0);
            expectWellFormedFrame(book, std::string(name(display)) + ", step " + std::to_string(step));
            if (HasFailure()) return;
        }
        EXPECT_GT(starts, 50) << "the walk should start many turns";
    }
}

TEST(Book, ForwardAndBackwardTurnsInFlightTogetherStayDistinct) {
    Book book = makeBook(40);
    book.jumpTo(3);
    ASSERT_TRUE(book.startTurn(kForward));  // leaf 3
    ASSERT_TRUE(book.startTurn(kForward));  // leaf 4; settles at 5
    book.setLatestTurnProgress(1.0);
    book.advance(0.01);  // leaf 4 lands; leaf 3 still turning
    ASSERT_EQ(flying(book.frame()).size(), 1u) << str(book.frame());
    ASSERT_TRUE(book.startTurn(kBackward)) << "leaf 4 has landed and may turn back";
    EXPECT_EQ(book.position(), 4);
    const BookFrame f = book.frame();
    expectWellFormedFrame(book, "one forward and one backward in flight");
    const std::vector<LeafDraw> rest = resting(f);
    const std::vector<LeafDraw> fly = flying(f);
    ASSERT_EQ(rest.size(), 2u) << str(f);
    ASSERT_EQ(fly.size(), 2u) << str(f);
    EXPECT_EQ(rest[0].leaf, 2) << str(f);
    EXPECT_EQ(rest[1].leaf, 5) << str(f);
    EXPECT_TRUE(fly[0].leaf == 3 && !fly[0].mirrored) << str(f);
    EXPECT_TRUE(fly[1].leaf == 4 && fly[1].mirrored) << str(f);
}

// =================================================================================================
// Book: jumps, page lookup, degenerate configurations.

TEST(Book, JumpToClampsToTheBookAndDropsTurnsInFlight) {
    for (Display display : {Display::Double, Display::Single}) {
        Book book = makeBook(9, display);
        const int last = book.lastPosition();
        for (int i = 0; i < 3; ++i) ASSERT_TRUE(book.startTurn(kForward));
        ASSERT_TRUE(book.animating());
        book.jumpTo(2);
        EXPECT_FALSE(book.animating()) << name(display);
        EXPECT_EQ(book.position(), 2) << name(display);
        EXPECT_TRUE(flying(book.frame()).empty()) << str(book.frame());
        book.jumpTo(-4);
        EXPECT_EQ(book.position(), 0) << name(display);
        book.jumpTo(last + 1);
        EXPECT_EQ(book.position(), last) << name(display);
        book.jumpTo(1 << 30);
        EXPECT_EQ(book.position(), last) << name(display);
        expectWellFormedFrame(book, name(display));
    }
}

TEST(Book, PositionOfPageIsTheSpreadShowingThatPageAndClamps) {
    for (int n : {1, 2, 5, 6, 40}) {
        Book dbl = makeBook(n);
        Book single = makeBook(n, Display::Single);
        for (int p = 0; p < n; ++p) {
            EXPECT_EQ(dbl.positionOfPage(p), (p + 1) / 2) << "double, pageCount " << n << ", page " << p;
            EXPECT_EQ(single.positionOfPage(p), p) << "single, pageCount " << n << ", page " << p;
            // And the page is indeed face up there.
            dbl.jumpTo(dbl.positionOfPage(p));
            const BookFrame f = dbl.frame();
            bool shown = false;
            for (int i = 0; i < f.count; ++i) {
                const LeafDraw& d = f.leaves[i];
                shown |= (d.curl.rho == 0.0 && d.frontPage == p) || (d.curl.rho == kPi && d.backPage == p);
            }
            EXPECT_TRUE(shown) << "page " << p << " of " << n << " at position " << dbl.position() << ": " << str(f);
        }
        EXPECT_EQ(dbl.positionOfPage(-1), 0);
        EXPECT_EQ(dbl.positionOfPage(-100), 0);
        EXPECT_EQ(dbl.positionOfPage(n), n / 2) << "past the end: the spread with the last page, pageCount " << n;
        EXPECT_EQ(dbl.positionOfPage(1 << 30), n / 2);
        EXPECT_EQ(single.positionOfPage(-7), 0);
        EXPECT_EQ(single.positionOfPage(n + 5), n - 1);
    }
}

TEST(Book, EmptyBookHasNoLeavesNoDrawsAndRefusesTurns) {
    for (int n : {0, -1, -40}) {
        for (Display display : {Display::Double, Display::Single}) {
            Book book = makeBook(n, display);
            const std::string where = std::string(name(display)) + ", pageCount " + std::to_string(n);
            EXPECT_EQ(book.config().pageCount, 0) << where << ": a negative count is treated as 0";
            EXPECT_EQ(book.leafCount(), 0) << where;
            EXPECT_EQ(book.lastPosition(), 0) << where;
            EXPECT_EQ(book.frame().count, 0) << where << ": " << str(book.frame());
            EXPECT_FALSE(book.startTurn(kForward)) << where;
            EXPECT_FALSE(book.startTurn(kBackward)) << where;
            EXPECT_FALSE(book.animating()) << where;
            EXPECT_EQ(book.firstVisiblePage(), kNoPage) << where;
            EXPECT_EQ(book.positionOfPage(3), 0) << where;
            book.jumpTo(5);
            EXPECT_EQ(book.position(), 0) << where;
            EXPECT_FALSE(book.isHardLeaf(0)) << where;
        }
    }
}

TEST(Book, NonPositiveOrNaNTurnSecondsMeansOneSecond) {
    for (double seconds : {0.0, -2.0, kNaN, -std::numeric_limits<double>::infinity()}) {
        Book book = makeBook(10, Display::Double, seconds);
        EXPECT_EQ(book.config().turnSeconds, 1.0) << "turnSeconds " << seconds;
        ASSERT_TRUE(book.startTurn(kForward));
        book.advance(0.5);
        const std::vector<LeafDraw> fly = flying(book.frame());
        ASSERT_EQ(fly.size(), 1u) << "turnSeconds " << seconds << ": " << str(book.frame());
        EXPECT_TRUE(sameCurl(fly[0].curl, sanitize(curlAt(0.5, CurlSchedule{}, kH))))
            << "turnSeconds " << seconds << ": " << str(fly[0].curl);
        EXPECT_FALSE(book.advance(0.5)) << "turnSeconds " << seconds;
    }
}

// =================================================================================================
// LeafPlacement.

struct Pose {
    Binding binding;
    bool mirrored;
    std::string str() const { return std::string(name(binding)) + (mirrored ? ", mirrored" : ""); }
};

std::vector<Pose> allPoses() {
    std::vector<Pose> poses;
    for (Binding b : kBindings)
        for (bool m : {false, true}) poses.push_back({b, m});
    return poses;
}

LeafDraw drawWith(const Pose& pose, const CurlParams& curl) {
    LeafDraw d;
    d.curl = curl;
    d.mirrored = pose.mirrored;
    return d;
}

dvec3 toWorld(const glm::dmat4& m, dvec3 p) { return dvec3(m * dvec4(p, 1.0)); }

using conecurl::testing::str;

// Axis-aligned rectangle in world x, y.
struct Rect {
    double x0, x1, y0, y1;
};

std::string str(const Rect& r) {
    std::ostringstream os;
    os << "x [" << r.x0 << ", " << r.x1 << "], y [" << r.y0 << ", " << r.y1 << "]";
    return os.str();
}

// Where a flat resting page lies in the world, from the model (not from the placement tables).
Rect sideRect(Binding b, bool turnedSide, double w, double h) {
    switch (b) {
        case Binding::Left: return turnedSide ? Rect{-w, 0, -h / 2, h / 2} : Rect{0, w, -h / 2, h / 2};
        case Binding::Right: return turnedSide ? Rect{0, w, -h / 2, h / 2} : Rect{-w, 0, -h / 2, h / 2};
        case Binding::Top: return turnedSide ? Rect{-h / 2, h / 2, 0, w} : Rect{-h / 2, h / 2, -w, 0};
    }
    return {};
}

Rect boundsOf(const std::vector<dvec3>& pts) {
    Rect r{pts[0].x, pts[0].x, pts[0].y, pts[0].y};
    for (dvec3 p : pts) {
        r.x0 = std::min(r.x0, p.x), r.x1 = std::max(r.x1, p.x);
        r.y0 = std::min(r.y0, p.y), r.y1 = std::max(r.y1, p.y);
    }
    return r;
}

bool nearRect(const Rect& a, const Rect& b, double tol) {
    return std::abs(a.x0 - b.x0) <= tol && std::abs(a.x1 - b.x1) <= tol && std::abs(a.y0 - b.y0) <= tol &&
           std::abs(a.y1 - b.y1) <= tol;
}

const dvec2 kCorners[] = {{0.0, 0.0}, {kW, 0.0}, {0.0, kH}, {kW, kH}};

TEST(LeafPlacement, PageToWorldIsARigidMotionWhoseDeterminantSignIsTheHandedness) {
    for (const Pose& pose : allPoses()) {
        const LeafPlacement pl = placeLeaf(pose.binding, pose.mirrored, kH);
        const dmat3 m(pl.pageToWorld);
        const dmat3 mtm = glm::transpose(m) * m;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(mtm[i][j], i == j ? 1.0 : 0.0, 1e-15) << pose.str() << ": M^T M [" << i << "][" << j << "]";
        EXPECT_TRUE(pl.handedness == 1.0 || pl.handedness == -1.0) << pose.str() << ": " << pl.handedness;
        EXPECT_NEAR(glm::determinant(m), pl.handedness, 1e-15) << pose.str();
        const glm::dmat4& a = pl.pageToWorld;
        EXPECT_TRUE(a[0][3] == 0.0 && a[1][3] == 0.0 && a[2][3] == 0.0 && a[3][3] == 1.0)
            << pose.str() << ": not affine";
        EXPECT_EQ(pl.facingIsBackPage, pose.mirrored) << pose.str();
        // Page z (out of the paper) stays world z: the viewer looks down on the unturned side.
        EXPECT_EQ(m[2], dvec3(0.0, 0.0, 1.0)) << pose.str();
    }
}

TEST(LeafPlacement, TheSpineMapsOntoTheWorldSpineForFlatAndCurledLeaves) {
    for (const Pose& pose : allPoses()) {
        const LeafPlacement pl = placeLeaf(pose.binding, pose.mirrored, kH);
        for (int j = 0; j <= 20; ++j) {
            const double y = kH * j / 20.0;
            const dvec3 want = pose.binding == Binding::Top ? dvec3(y - kH / 2, 0.0, 0.0) : dvec3(0.0, y - kH / 2, 0.0);
            const dvec3 got = toWorld(pl.pageToWorld, {0.0, y, 0.0});
            EXPECT_LT(glm::length(got - want), 1e-15) << pose.str() << ", y " << y << ": " << str(got);
            for (double t : {0.1, 0.3, 0.6, 0.9}) {
                const dvec3 curled = leafPointToWorld(drawWith(pose, curlAt(t, CurlSchedule{}, kH)), pose.binding, kH,
                                                      {0.0, y});
                EXPECT_LT(glm::length(curled - want), 1e-13) << pose.str() << ", t " << t << ", y " << y << ": "
                                                             << str(curled);
            }
        }
    }
}

TEST(LeafPlacement, RestingLeavesLieOnTheirSideOfTheSpine) {
    // Unturned: Left x in [0, w], Right x in [-w, 0], Top y in [-w, 0]; turned: the other side.
    // A mirrored leaf at rho 0 lies where the turned leaf lies (backward turns start there).
    for (const Pose& pose : allPoses()) {
        for (bool turned : {false, true}) {
            std::vector<dvec3> pts;
            for (int i = 0; i <= 8; ++i)
                for (int j = 0; j <= 8; ++j)
                    pts.push_back(leafPointToWorld(drawWith(pose, flatCurl(turned)), pose.binding, kH,
                                                   {kW * i / 8.0, kH * j / 8.0}));
            const Rect got = boundsOf(pts);
            const Rect want = sideRect(pose.binding, turned != pose.mirrored, kW, kH);
            EXPECT_TRUE(nearRect(got, want, 1e-12))
                << pose.str() << ", rho " << (turned ? "pi" : "0") << ": lies at " << str(got) << ", want " << str(want);
            double maxZ = 0.0;
            for (dvec3 p : pts) maxZ = std::max(maxZ, std::abs(p.z));
            EXPECT_LT(maxZ, 1e-12) << pose.str() << ": a resting leaf lies in the z = 0 plane";
        }
    }
}

// Which side of a flat leaf the viewer (on +z) sees, found from the surface normal: +z side (facing)
// or the other (away).
bool viewerSeesFacingSide(const Pose& pose, const CurlParams& curl) {
    const LeafPlacement pl = placeLeaf(pose.binding, pose.mirrored, kH);
    const dvec3 n = conecurl::curlNormalAnalytic({kW / 2, kH / 2}, curl);  // page +z side's normal
    return (dmat3(pl.pageToWorld) * n).z > 0.0;
}

TEST(LeafPlacement, TheSideTheViewerSeesReadsUprightForEveryBindingAndPose) {
    // For each pose: take the visible side's uv map, and check across the visible page that u grows with
    // world x, v falls as world y grows (image v runs down), nothing is sheared or rotated, and the
    // image's corners sit on the page's corners.
    for (const Pose& pose : allPoses()) {
        const LeafPlacement pl = placeLeaf(pose.binding, pose.mirrored, kH);
        for (bool turned : {false, true}) {
            const CurlParams curl = flatCurl(turned);
            const std::string where = pose.str() + ", rho " + (turned ? "pi" : "0");
            const bool facing = viewerSeesFacingSide(pose, curl);
            // rho 0 shows the +z side, rho pi the other.
            EXPECT_EQ(facing, !turned) << where;
            // The visible page: the front while the leaf lies unturned, the back once it lies turned.
            const bool onTurnedSide = turned != pose.mirrored;
            const bool seesBackPage = facing ? pl.facingIsBackPage : !pl.facingIsBackPage;
            EXPECT_EQ(seesBackPage, onTurnedSide) << where << ": the visible side shows the wrong page";

            const dmat3& uvMap = facing ? pl.facingUv : pl.awayUv;
            auto uvAt = [&](dvec2 q) { return dvec2(uvMap * dvec3(q.x / kW, q.y / kH, 1.0)); };
            auto worldAt = [&](dvec2 q) {
                return dvec2(leafPointToWorld(drawWith(pose, curl), pose.binding, kH, q));
            };
            // Numerical Jacobians over the whole page: d(X, Y)/d(x, y) and d(u, v)/d(x, y).
            const dvec2 q0{0.0, 0.0}, qx{kW, 0.0}, qy{0.0, kH};
            const dvec2 dWx = (worldAt(qx) - worldAt(q0)) / kW, dWy = (worldAt(qy) - worldAt(q0)) / kH;
            const dvec2 dUx = (uvAt(qx) - uvAt(q0)) / kW, dUy = (uvAt(qy) - uvAt(q0)) / kH;
            // d(uv)/d(XY) = d(uv)/d(xy) * inverse(d(XY)/d(xy)).
            const double det = dWx.x * dWy.y - dWy.x * dWx.y;
            ASSERT_GT(std::abs(det), 0.5) << where;
            const double ix_X = dWy.y / det, ix_Y = -dWy.x / det;  // dx/dX, dx/dY
            const double iy_X = -dWx.y / det, iy_Y = dWx.x / det;  // dy/dX, dy/dY
            const double du_dX = dUx.x * ix_X + dUy.x * iy_X;
            const double du_dY = dUx.x * ix_Y + dUy.x * iy_Y;
            const double dv_dX = dUx.y * ix_X + dUy.y * iy_X;
            const double dv_dY = dUx.y * ix_Y + dUy.y * iy_Y;
            const Rect page = sideRect(pose.binding, onTurnedSide, kW, kH);
            std::ostringstream grads;
            grads << where << ": du/dX " << du_dX << ", du/dY " << du_dY << ", dv/dX " << dv_dX << ", dv/dY " << dv_dY;
            EXPECT_GT(du_dX, 0.0) << grads.str() << " (image mirrored left-right)";
            EXPECT_LT(dv_dY, 0.0) << grads.str() << " (image upside down)";
            EXPECT_LT(std::abs(du_dY), 1e-9) << grads.str() << " (image rotated)";
            EXPECT_LT(std::abs(dv_dX), 1e-9) << grads.str() << " (image rotated)";
            // The image spans the page exactly: u over its world width, v over its height.
            EXPECT_NEAR(du_dX, 1.0 / (page.x1 - page.x0), 1e-9) << grads.str();
            EXPECT_NEAR(dv_dY, -1.0 / (page.y1 - page.y0), 1e-9) << grads.str();
            // Corners: image (0, 0) at the top left of the visible page, (1, 1) at its bottom right.
            for (dvec2 q : kCorners) {
                const dvec2 uv = uvAt(q);
                const dvec2 w = worldAt(q);
                EXPECT_TRUE((uv.x == 0.0 || uv.x == 1.0) && (uv.y == 0.0 || uv.y == 1.0))
                    << where << ": page corner (" << q.x << ", " << q.y << ") has uv (" << uv.x << ", " << uv.y << ")";
                const double wantX = uv.x == 0.0 ? page.x0 : page.x1;
                const double wantY = uv.y == 0.0 ? page.y1 : page.y0;
                EXPECT_NEAR(w.x, wantX, 1e-12) << where << ": uv (" << uv.x << ", " << uv.y << ")";
                EXPECT_NEAR(w.y, wantY, 1e-12) << where << ": uv (" << uv.x << ", " << uv.y << ")";
            }
        }
    }
}

TEST(LeafPlacement, ABackwardTurnStartsOnExactlyTheImageAForwardTurnEndsOn) {
    // A leaf resting turned (rho pi) and the same leaf mirrored at rho 0 (a backward turn's first frame)
    // must put every page point at the same world point with the same texel and the same page visible;
    // likewise unturned (rho 0) against mirrored rho pi (a backward turn's last frame).
    for (Binding b : kBindings) {
        for (bool turned : {false, true}) {
            const Pose fwd{b, false};
            const Pose bwd{b, true};
            const CurlParams cf = flatCurl(turned);
            const CurlParams cb = flatCurl(!turned);
            const LeafPlacement pf = placeLeaf(b, false, kH);
            const LeafPlacement pb = placeLeaf(b, true, kH);
            const bool facingF = viewerSeesFacingSide(fwd, cf);
            const bool facingB = viewerSeesFacingSide(bwd, cb);
            const bool backF = facingF ? pf.facingIsBackPage : !pf.facingIsBackPage;
            const bool backB = facingB ? pb.facingIsBackPage : !pb.facingIsBackPage;
            const std::string where = std::string(name(b)) + (turned ? ", turned" : ", unturned");
            EXPECT_EQ(backF, backB) << where << ": a different page shows";
            const dmat3& uvF = facingF ? pf.facingUv : pf.awayUv;
            const dmat3& uvB = facingB ? pb.facingUv : pb.awayUv;
            for (int i = 0; i <= 4; ++i) {
                for (int j = 0; j <= 4; ++j) {
                    const dvec2 q{kW * i / 4.0, kH * j / 4.0};
                    const dvec3 wf = leafPointToWorld(drawWith(fwd, cf), b, kH, q);
                    const dvec3 wb = leafPointToWorld(drawWith(bwd, cb), b, kH, q);
                    EXPECT_LT(glm::length(wf - wb), 1e-12) << where << ": " << str(wf) << " vs " << str(wb);
                    const dvec3 s{q.x / kW, q.y / kH, 1.0};
                    EXPECT_LT(glm::length(dvec2(uvF * s) - dvec2(uvB * s)), 1e-15) << where << ", q (" << q.x << ", "
                                                                                   << q.y << ")";
                }
            }
        }
    }
}

TEST(LeafPlacement, LeafPointToWorldIsPageToWorldOfTheCurledPoint) {
    // Against the placement matrix and against the binding table written out by hand.
    auto byHand = [](Binding b, bool mirrored, dvec3 c) {
        if (mirrored) c.x = -c.x;
        switch (b) {
            case Binding::Left: return dvec3(c.x, c.y - kH / 2, c.z);
            case Binding::Right: return dvec3(-c.x, c.y - kH / 2, c.z);
            case Binding::Top: return dvec3(c.y - kH / 2, -c.x, c.z);
        }
        return dvec3(0.0);
    };
    double worst = 0.0;
    for (const Pose& pose : allPoses()) {
        const LeafPlacement pl = placeLeaf(pose.binding, pose.mirrored, kH);
        for (int k = 0; k <= 20; ++k) {
            const CurlParams curl = curlAt(k / 20.0, CurlSchedule{}, kH);
            for (int i = 0; i <= 7; ++i) {
                for (int j = 0; j <= 7; ++j) {
                    const dvec2 q{kW * i / 7.0, kH * j / 7.0};
                    const dvec3 c = conecurl::curlPoint(q, curl);
                    const dvec3 got = leafPointToWorld(drawWith(pose, curl), pose.binding, kH, q);
                    const double e1 = glm::length(got - toWorld(pl.pageToWorld, c));
                    const double e2 = glm::length(got - byHand(pose.binding, pose.mirrored, c));
                    worst = std::max({worst, e1, e2});
                    ASSERT_LT(e1, 1e-14) << pose.str() << ", t " << k / 20.0 << ", q (" << q.x << ", " << q.y << ")";
                    ASSERT_LT(e2, 1e-14) << pose.str() << ", t " << k / 20.0 << ", q (" << q.x << ", " << q.y << ")";
                }
            }
        }
    }
    // Rigid: distances between page points on the curled leaf are those of the curled page.
    const CurlParams mid = curlAt(0.3, CurlSchedule{}, kH);
    for (const Pose& pose : allPoses()) {
        const dvec2 a{0.1, 0.2}, b{0.6, 0.9};
        const double d = glm::length(leafPointToWorld(drawWith(pose, mid), pose.binding, kH, a) -
                                     leafPointToWorld(drawWith(pose, mid), pose.binding, kH, b));
        EXPECT_NEAR(d, glm::length(conecurl::curlPoint(a, mid) - conecurl::curlPoint(b, mid)), 1e-14) << pose.str();
    }
}

TEST(LeafPlacement, BookFramesPlaceTheirRestingLeavesOnTheRightSides) {
    // Book and placement together: at a double spread the turned leaf and the unturned leaf lie on
    // opposite sides of the spine, for each binding.
    for (Binding b : kBindings) {
        BookConfig config;
        config.pageCount = 10;
        config.binding = b;
        config.pageWidth = kW;
        config.pageHeight = kH;
        Book book(config);
        book.jumpTo(2);
        const BookFrame f = book.frame();
        ASSERT_EQ(f.count, 2) << str(f);
        for (int i = 0; i < f.count; ++i) {
            const LeafDraw& d = f.leaves[i];
            std::vector<dvec3> pts;
            for (dvec2 q : kCorners) pts.push_back(leafPointToWorld(d, b, kH, q));
            const Rect got = boundsOf(pts);
            const Rect want = sideRect(b, d.curl.rho == kPi, kW, kH);
            EXPECT_TRUE(nearRect(got, want, 1e-12)) << name(b) << ": " << str(d) << " lies at " << str(got);
        }
    }
}

TEST(LeafPlacement, ViewFrameHoldsBothPagesInDoubleAndOnlyTheUnturnedOneInSingle) {
    for (Binding b : kBindings) {
        auto pageRect = [&](bool turned) {
            std::vector<dvec3> pts;
            for (dvec2 q : kCorners) pts.push_back(leafPointToWorld(drawWith({b, false}, flatCurl(turned)), b, kH, q));
            return boundsOf(pts);
        };
        auto frameRect = [](const ViewFrame& v) {
            return Rect{v.center.x - v.halfExtent.x, v.center.x + v.halfExtent.x, v.center.y - v.halfExtent.y,
                        v.center.y + v.halfExtent.y};
        };
        const Rect unturned = pageRect(false);
        const Rect turned = pageRect(true);
        const Rect both{std::min(unturned.x0, turned.x0), std::max(unturned.x1, turned.x1),
                        std::min(unturned.y0, turned.y0), std::max(unturned.y1, turned.y1)};
        const Rect dbl = frameRect(viewFrameFor(Display::Double, b, kW, kH));
        const Rect single = frameRect(viewFrameFor(Display::Single, b, kW, kH));
        // Exactly the pages' extent: all of them shows, nothing else is framed.
        EXPECT_TRUE(nearRect(dbl, both, 1e-12)) << name(b) << " double frames " << str(dbl) << ", pages span " << str(both);
        EXPECT_TRUE(nearRect(single, unturned, 1e-12))
            << name(b) << " single frames " << str(single) << ", the unturned page is " << str(unturned);
        // The turned page's middle is outside the single frame.
        const double cx = 0.5 * (turned.x0 + turned.x1), cy = 0.5 * (turned.y0 + turned.y1);
        EXPECT_FALSE(cx > single.x0 && cx < single.x1 && cy > single.y0 && cy < single.y1) << name(b);
    }
}

}  // namespace

namespace {

TEST(Book, SetDisplayKeepsTheFirstVisiblePageInViewBothWaysAndLandsTurnsInFlight) {
    BookConfig config;
    config.pageCount = 9;
    Book book(config);
    book.jumpTo(3);  // pages 5 and 6 open
    ASSERT_EQ(book.firstVisiblePage(), 5);
    ASSERT_TRUE(book.startTurn(conecurl::TurnDirection::Forward));
    book.setDisplay(Display::Single);
    EXPECT_FALSE(book.animating());
    EXPECT_EQ(book.config().display, Display::Single);
    EXPECT_EQ(book.leafCount(), 9);
    EXPECT_EQ(book.firstVisiblePage(), 7);  // the turn landed: the first page of where it settles (7, 8) stays
    book.jumpTo(5);
    book.setDisplay(Display::Single);       // the same display: nothing moves
    EXPECT_EQ(book.firstVisiblePage(), 5);
    book.jumpTo(8);
    book.setDisplay(Display::Double);
    EXPECT_EQ(book.position(), 4);          // pages 7 and 8
    EXPECT_EQ(book.firstVisiblePage(), 7);
    Book empty(BookConfig{});
    empty.setDisplay(Display::Single);
    EXPECT_EQ(empty.position(), 0);
}

TEST(BookSetPages, NativeNewPageCountLandsTurnsKeepsTheFirstVisiblePageIndexAndClampsIt) {
    BookConfig config;
    config.pageCount = 10;
    Book book(config);
    book.jumpTo(3);  // pages 5 and 6 open
    ASSERT_TRUE(book.startTurn(conecurl::TurnDirection::Forward));
    book.setPages(14, {});
    EXPECT_FALSE(book.animating());
    EXPECT_EQ(book.config().pageCount, 14);
    EXPECT_EQ(book.leafCount(), 7);
    EXPECT_EQ(book.lastPosition(), 7);
    EXPECT_EQ(book.firstVisiblePage(), 7);  // the turn landed on pages 7, 8: page 7 stays in view
    book.jumpTo(book.positionOfPage(11));
    EXPECT_EQ(book.firstVisiblePage(), 11);
    book.setPages(4, {});                   // page 11 is gone: the last spread of the shorter book
    EXPECT_EQ(book.position(), 2);
    EXPECT_EQ(book.firstVisiblePage(), 3);
    EXPECT_EQ(book.frame().count, 1);       // leaf 1 turned (pages 2, 3); no unturned leaf left
}

TEST(BookSetPages, NativeHardPagesFollowTheNewListAndAreCutToThePageCount) {
    BookConfig config;
    config.pageCount = 6;
    config.hardPages = {true, false, false, false, false, true};
    Book book(config);
    EXPECT_TRUE(book.isHardLeaf(0));
    EXPECT_TRUE(book.isHardLeaf(2));
    book.setPages(8, {false, false, true, false, false, false, false, true, true, true});
    EXPECT_FALSE(book.isHardLeaf(0));
    EXPECT_TRUE(book.isHardLeaf(1));   // page 2
    EXPECT_FALSE(book.isHardLeaf(2));
    EXPECT_TRUE(book.isHardLeaf(3));   // page 7
    EXPECT_EQ(book.config().hardPages.size(), 8u);  // entries past the page count are dropped
    Book single(BookConfig{3, Display::Single});
    single.jumpTo(2);
    single.setPages(1, {});
    EXPECT_EQ(single.position(), 0);
    EXPECT_EQ(single.firstVisiblePage(), 0);
    single.setPages(0, {});
    EXPECT_EQ(single.firstVisiblePage(), kNoPage);
    EXPECT_EQ(single.frame().count, 0);
}

}  // namespace
