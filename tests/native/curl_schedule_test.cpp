// Native (GoogleTest via CTest) tests of the three-phase cone schedule: they hold curlAt() to the
// table in docs/cone-curl-math.md over a dense grid of t, plus its clamping and easing rules.
#include "curl_schedule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using conecurl::CurlParams;
using conecurl::CurlSchedule;
using conecurl::curlAt;
using conecurl::easeSine;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// Every 1e-4 of the turn, end points included: 10 001 samples, far denser than a frame rate.
std::vector<double> denseTimes() {
    constexpr int kSteps = 10000;
    std::vector<double> ts;
    ts.reserve(kSteps + 1);
    for (int i = 0; i <= kSteps; ++i) ts.push_back(static_cast<double>(i) / kSteps);
    return ts;
}

bool isFinite(const CurlParams& p) {
    return std::isfinite(p.theta) && std::isfinite(p.apexY) && std::isfinite(p.rho);
}

std::string describe(const CurlParams& p) {
    std::ostringstream os;
    os.precision(17);
    os << "{theta=" << p.theta << " (" << p.theta / kDeg << " deg), apexY=" << p.apexY
       << ", rho=" << p.rho << "}";
    return os.str();
}

// An independent transcription of the doc's table, with its constants written in degrees and page
// units exactly as the table gives them (not read from CurlSchedule), for a page 1 unit tall.
CurlParams docTable(double t) {
    auto lerp = [](double f, double a, double b) { return a + (b - a) * f; };
    auto ease = [](double dt, double k) { return std::sin(kPi / 2.0 * std::pow(dt, k)); };
    CurlParams p{};
    if (t <= 0.15) {
        const double dt = t / 0.15;
        p.theta = lerp(ease(dt, 0.05), 90.0 * kDeg, 8.0 * kDeg);
        p.apexY = lerp(ease(dt, 0.5), -15.0, -2.5);
    } else if (t <= 0.4) {
        const double dt = (t - 0.15) / 0.25;
        p.theta = lerp(dt, 8.0 * kDeg, 6.0 * kDeg);
        p.apexY = lerp(dt, -2.5, -3.5);
    } else {
        const double dt = (t - 0.4) / 0.6;
        p.theta = lerp(ease(dt, 10.0), 6.0 * kDeg, 90.0 * kDeg);
        p.apexY = lerp(ease(dt, 2.0), -3.5, -15.0);
    }
    p.rho = kPi * t;
    return p;
}

// The boundary rows are exact in the table; 1e-12 leaves room for a few roundings of sin/pow/lerp
// on values of size <= 15 (1 ulp of 15 is 1.8e-15).
constexpr double kTableTol = 1e-12;

TEST(CurlSchedule, MatchesNuonTableAtPhaseBoundaries) {
    struct Row {
        double t, thetaDeg, apexY, rhoDeg;
    };
    const Row rows[] = {
        {0.0, 90.0, -15.0, 0.0},
        {0.15, 8.0, -2.5, 27.0},
        {0.4, 6.0, -3.5, 72.0},
        {1.0, 90.0, -15.0, 180.0},
    };
    for (const Row& row : rows) {
        const CurlParams p = curlAt(row.t);
        SCOPED_TRACE("t = " + std::to_string(row.t) + ": " + describe(p));
        EXPECT_NEAR(p.theta, row.thetaDeg * kDeg, kTableTol);
        EXPECT_NEAR(p.apexY, row.apexY, kTableTol);
        EXPECT_NEAR(p.rho, row.rhoDeg * kDeg, kTableTol);
    }
}

TEST(CurlSchedule, DefaultConstantsAreNuonsInRadians) {
    const CurlSchedule s;
    EXPECT_DOUBLE_EQ(s.phase1End, 0.15);
    EXPECT_DOUBLE_EQ(s.phase2End, 0.40);
    EXPECT_DOUBLE_EQ(s.thetaRest, 90.0 * kDeg);
    EXPECT_DOUBLE_EQ(s.thetaPhase1, 8.0 * kDeg);
    EXPECT_DOUBLE_EQ(s.thetaPhase2, 6.0 * kDeg);
    EXPECT_DOUBLE_EQ(s.apexRest, -15.0);
    EXPECT_DOUBLE_EQ(s.apexPhase1, -2.5);
    EXPECT_DOUBLE_EQ(s.apexPhase2, -3.5);
    EXPECT_DOUBLE_EQ(s.thetaEasePhase1, 0.05);
    EXPECT_DOUBLE_EQ(s.apexEasePhase1, 0.5);
    EXPECT_DOUBLE_EQ(s.thetaEasePhase3, 10.0);
    EXPECT_DOUBLE_EQ(s.apexEasePhase3, 2.0);
}

TEST(CurlSchedule, MatchesDocTableFormulasEverywhereOnDenseTimeGrid) {
    double worst = 0.0;
    double worstT = 0.0;
    for (double t : denseTimes()) {
        const CurlParams got = curlAt(t);
        const CurlParams want = docTable(t);
        const double err = std::max({std::abs(got.theta - want.theta), std::abs(got.apexY - want.apexY),
                                     std::abs(got.rho - want.rho)});
        if (!(err <= worst)) {  // also catches NaN
            worst = err;
            worstT = t;
        }
    }
    EXPECT_LE(worst, kTableTol) << "worst at t = " << worstT << ": got " << describe(curlAt(worstT))
                                << ", table " << describe(docTable(worstT));
}

// The doc: the parameters are continuous in value (not slope) at 0.15 and 0.4. Just either side of a
// boundary (t +/- 1e-9) the largest one-sided slope is |dAy/dt| = 1/0.25 = 4 (phase 2 is linear; the
// eased sides have zero slope there), so a continuous schedule differs by <= ~1e-8; a jump would be
// >= the smallest step in the table (2 deg = 0.035 rad, 1 unit of apex). 1e-7 separates the two.
TEST(CurlSchedule, IsContinuousInValueAcrossPhaseBoundaries) {
    constexpr double kEps = 1e-9;
    constexpr double kTol = 1e-7;
    for (double H : {1.0, 1.375, 2.0}) {
        for (double b : {0.15, 0.4}) {
            const CurlParams below = curlAt(b - kEps, CurlSchedule{}, H);
            const CurlParams at = curlAt(b, CurlSchedule{}, H);
            const CurlParams above = curlAt(b + kEps, CurlSchedule{}, H);
            SCOPED_TRACE("boundary t = " + std::to_string(b) + ", H = " + std::to_string(H));
            EXPECT_NEAR(below.theta, above.theta, kTol);
            EXPECT_NEAR(below.apexY, above.apexY, kTol * H);
            EXPECT_NEAR(below.rho, above.rho, kTol);
            EXPECT_NEAR(at.theta, above.theta, kTol);
            EXPECT_NEAR(at.apexY, above.apexY, kTol * H);
        }
    }
}

// Ay is a length and scales with the page; the angles do not. curlAt multiplies once by H, so apexY
// must be H times the unit-page value to within one rounding (relative 2.3e-16, asserted at 1e-15).
TEST(CurlSchedule, PageHeightScalesApexButNotThetaOrRho) {
    for (double H : {1.375, 2.0, 0.5}) {
        double worstApexRel = 0.0;
        double worstAngle = 0.0;
        double worstT = 0.0;
        for (double t : denseTimes()) {
            const CurlParams unit = curlAt(t);
            const CurlParams tall = curlAt(t, CurlSchedule{}, H);
            const double apexRel = std::abs(tall.apexY - H * unit.apexY) / std::abs(H * unit.apexY);
            const double angle = std::max(std::abs(tall.theta - unit.theta), std::abs(tall.rho - unit.rho));
            if (!(apexRel <= worstApexRel)) {
                worstApexRel = apexRel;
                worstT = t;
            }
            if (!(angle <= worstAngle)) worstAngle = angle;
        }
        EXPECT_LE(worstApexRel, 1e-15) << "H = " << H << ", worst at t = " << worstT;
        EXPECT_EQ(worstAngle, 0.0) << "H = " << H << ": theta or rho depends on the page height";
    }
    // The boundary rows for a taller page: Ay scaled, angles unchanged.
    const CurlParams p = curlAt(0.15, CurlSchedule{}, 2.0);
    EXPECT_NEAR(p.apexY, -5.0, kTableTol);
    EXPECT_NEAR(p.theta, 8.0 * kDeg, kTableTol);
    EXPECT_NEAR(curlAt(0.0, CurlSchedule{}, 1.375).apexY, -15.0 * 1.375, kTableTol);
}

// The constants are data: a schedule with other phase ends, angles, apexes and exponents is evaluated
// with those values and none of Nuon's.
TEST(CurlSchedule, HonoursCustomScheduleConstants) {
    CurlSchedule s;
    s.phase1End = 0.3;
    s.phase2End = 0.6;
    s.thetaRest = 80.0 * kDeg;
    s.thetaPhase1 = 20.0 * kDeg;
    s.thetaPhase2 = 10.0 * kDeg;
    s.apexRest = -10.0;
    s.apexPhase1 = -1.0;
    s.apexPhase2 = -2.0;
    s.thetaEasePhase1 = 1.0;
    s.apexEasePhase1 = 1.0;
    s.thetaEasePhase3 = 1.0;
    s.apexEasePhase3 = 3.0;
    const double H = 1.5;

    struct Expect {
        double t, theta, apex;
    };
    const double e1 = std::sin(kPi / 4.0);                    // ease(0.5, 1)
    const double e3 = std::sin(kPi / 2.0 * std::pow(0.5, 3));  // ease(0.5, 3)
    const Expect cases[] = {
        {0.0, 80.0 * kDeg, -10.0},
        {0.15, (80.0 + (20.0 - 80.0) * e1) * kDeg, -10.0 + 9.0 * e1},  // phase 1, dt = 0.5
        {0.3, 20.0 * kDeg, -1.0},
        {0.45, 15.0 * kDeg, -1.5},  // phase 2, dt = 0.5, linear
        {0.6, 10.0 * kDeg, -2.0},
        {0.8, (10.0 + 70.0 * e1) * kDeg, -2.0 - 8.0 * e3},  // phase 3, dt = 0.5
        {1.0, 80.0 * kDeg, -10.0},
    };
    for (const Expect& c : cases) {
        const CurlParams p = curlAt(c.t, s, H);
        SCOPED_TRACE("t = " + std::to_string(c.t) + ": " + describe(p));
        EXPECT_NEAR(p.theta, c.theta, kTableTol);
        EXPECT_NEAR(p.apexY, c.apex * H, kTableTol);
        EXPECT_NEAR(p.rho, kPi * c.t, kTableTol);
    }
    // And the default schedule is not what came out.
    EXPECT_GT(std::abs(curlAt(0.3, s).theta - curlAt(0.3).theta), 0.1);
}

TEST(CurlSchedule, RhoIsPiTimesT) {
    double worst = 0.0;
    double worstT = 0.0;
    for (double t : denseTimes()) {
        const double err = std::abs(curlAt(t).rho - kPi * t);
        if (!(err <= worst)) {
            worst = err;
            worstT = t;
        }
    }
    // rho = kPi * t is one multiplication: the same rounding as the reference, so exact.
    EXPECT_EQ(worst, 0.0) << "worst at t = " << worstT;
}

// The deformation is only defined for 0 < theta <= pi/2 (sin(theta) divides beta, pi/2 is flat) and
// an apex below the page; the schedule itself must stay there, without relying on sanitize().
TEST(CurlSchedule, ThetaStaysInOpenZeroToHalfPiAndApexBelowPage) {
    for (double H : {1.0, 1.375, 2.0}) {
        double minTheta = std::numeric_limits<double>::infinity();
        double maxTheta = -minTheta;
        double maxApex = -minTheta;
        double tMaxTheta = 0.0;
        double tMaxApex = 0.0;
        for (int i = 0; i <= 100000; ++i) {  // step 1e-5
            const double t = i / 100000.0;
            const CurlParams p = curlAt(t, CurlSchedule{}, H);
            ASSERT_TRUE(isFinite(p)) << "t = " << t << ": " << describe(p);
            minTheta = std::min(minTheta, p.theta);
            if (p.theta > maxTheta) {
                maxTheta = p.theta;
                tMaxTheta = t;
            }
            if (p.apexY > maxApex) {
                maxApex = p.apexY;
                tMaxApex = t;
            }
        }
        SCOPED_TRACE("H = " + std::to_string(H));
        EXPECT_GT(minTheta, 0.0);
        EXPECT_NEAR(minTheta, 6.0 * kDeg, 1e-12);  // the table's smallest angle
        EXPECT_LE(maxTheta, kPi / 2.0) << "at t = " << tMaxTheta;
        EXPECT_LT(maxApex, 0.0) << "at t = " << tMaxApex;
        EXPECT_NEAR(maxApex, -2.5 * H, 1e-12);  // the table's highest apex, at t = 0.15
    }
}

TEST(CurlSchedule, TimeOutsideUnitIntervalOrNaNClampsToRestingStates) {
    const CurlParams start = curlAt(0.0);
    const CurlParams end = curlAt(1.0);
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double t : {-1e-12, -0.1, -1.0, -1e300, -inf, -0.0, nan, -nan}) {
        const CurlParams p = curlAt(t);
        SCOPED_TRACE("t = " + std::to_string(t) + ": " + describe(p));
        ASSERT_TRUE(isFinite(p));
        EXPECT_EQ(p.theta, start.theta);
        EXPECT_EQ(p.apexY, start.apexY);
        EXPECT_EQ(p.rho, 0.0);
    }
    for (double t : {1.0 + 1e-12, 1.1, 2.0, 1e300, inf}) {
        const CurlParams p = curlAt(t);
        SCOPED_TRACE("t = " + std::to_string(t) + ": " + describe(p));
        ASSERT_TRUE(isFinite(p));
        EXPECT_EQ(p.theta, end.theta);
        EXPECT_EQ(p.apexY, end.apexY);
        EXPECT_EQ(p.rho, end.rho);
    }
    // Both resting states are the flat page (theta = pi/2) with the resting apex.
    EXPECT_NEAR(start.theta, kPi / 2.0, kTableTol);
    EXPECT_NEAR(end.theta, kPi / 2.0, kTableTol);
    EXPECT_NEAR(curlAt(nan, CurlSchedule{}, 2.0).apexY, -30.0, kTableTol);
}

TEST(CurlSchedule, EaseSineFixesEndpointsAndIsMonotone) {
    for (double k : {0.05, 0.5, 1.0, 2.0, 10.0}) {
        SCOPED_TRACE("k = " + std::to_string(k));
        EXPECT_EQ(easeSine(0.0, k), 0.0);
        EXPECT_EQ(easeSine(1.0, k), 1.0);
        // dt is clamped to [0, 1].
        EXPECT_EQ(easeSine(-0.5, k), 0.0);
        EXPECT_EQ(easeSine(1.5, k), 1.0);
        double prev = easeSine(0.0, k);
        double worstDrop = 0.0;
        double worstDt = 0.0;
        for (int i = 1; i <= 100000; ++i) {  // step 1e-5
            const double dt = i / 100000.0;
            const double e = easeSine(dt, k);
            ASSERT_TRUE(e >= 0.0 && e <= 1.0) << "dt = " << dt << ": " << e;
            if (prev - e > worstDrop) {
                worstDrop = prev - e;
                worstDt = dt;
            }
            prev = e;
        }
        // sin(pi/2 u) rises with u = dt^k on [0, 1]; glibc's pow and sin keep that order on this grid
        // bit for bit, so the check has no tolerance.
        EXPECT_EQ(worstDrop, 0.0) << "decreases at dt = " << worstDt;
    }
}

}  // namespace

// --- the smooth schedule (schedule: 'smooth') ---------------------------------------------------------

namespace {
CurlSchedule smoothSchedule() {
    CurlSchedule s;
    s.smooth = true;
    return s;
}
}  // namespace

// The smooth schedule goes through the paper's four key poses exactly, and rho is the paper's.
TEST(SmoothCurlSchedule, PassesThroughThePapersKeyPoses) {
    const CurlSchedule paper;
    const CurlSchedule smooth = smoothSchedule();
    for (const double t : {0.0, paper.phase1End, paper.phase2End, 1.0}) {
        const CurlParams a = curlAt(t, paper, 1.25);
        const CurlParams b = curlAt(t, smooth, 1.25);
        EXPECT_NEAR(a.theta, b.theta, 1e-12) << "t=" << t;
        EXPECT_NEAR(a.apexY, b.apexY, 1e-12) << "t=" << t;
        EXPECT_DOUBLE_EQ(a.rho, b.rho);
    }
    for (int i = 0; i <= 100; ++i) EXPECT_DOUBLE_EQ(curlAt(i / 100.0, smooth).rho, curlAt(i / 100.0, paper).rho);
}

// One-sided slopes (finite differences just below and above) at a time t.
static std::pair<double, double> slopesAt(const CurlSchedule& s, double t, double CurlParams::*field) {
    const double h = 1e-7;
    const double below = (curlAt(t, s).*field - curlAt(t - h, s).*field) / h;
    const double above = (curlAt(t + h, s).*field - curlAt(t, s).*field) / h;
    return {below, above};
}

// At the joins the smooth schedule's slopes match from both sides (continuous first derivative); the
// paper's do not (this is what the smooth one is for), and the smooth one starts and ends at rest.
TEST(SmoothCurlSchedule, SlopesAreEqualAtTheJoinsWhereThePapersJump) {
    const CurlSchedule paper;
    const CurlSchedule smooth = smoothSchedule();
    for (const double join : {paper.phase1End, paper.phase2End}) {
        for (double CurlParams::*field : {&CurlParams::theta, &CurlParams::apexY}) {
            const auto [below, above] = slopesAt(smooth, join, field);
            EXPECT_NEAR(below, above, 1e-3 * (1.0 + std::abs(below))) << "join " << join;
            const auto [paperBelow, paperAbove] = slopesAt(paper, join, field);
            // theta's slope jumps by 0.14 rad per unit of t (6-8 degrees over phase 2), Ay's by 4 page heights.
            EXPECT_GT(std::abs(paperBelow - paperAbove), 0.1) << "the paper's slope jumps at " << join;
        }
    }
    // At rest (t = 0 and 1) the slope is zero: over a step of 1e-8 the pose moves by < 1e-5 of it.
    const double h = 1e-8;
    for (double CurlParams::*field : {&CurlParams::theta, &CurlParams::apexY}) {
        EXPECT_NEAR((curlAt(h, smooth).*field - curlAt(0.0, smooth).*field) / h, 0.0, 1e-3);
        EXPECT_NEAR((curlAt(1.0, smooth).*field - curlAt(1.0 - h, smooth).*field) / h, 0.0, 1e-3);
    }
}

// Between two key poses the smooth schedule stays between them: it never curls tighter, nor lifts the
// apex further, than the paper's poses do (within the paper's envelope).
TEST(SmoothCurlSchedule, StaysBetweenNeighbouringKeyPoses) {
    const CurlSchedule s = smoothSchedule();
    const double keys[4] = {0.0, s.phase1End, s.phase2End, 1.0};
    const double thetas[4] = {s.thetaRest, s.thetaPhase1, s.thetaPhase2, s.thetaRest};
    const double apexes[4] = {s.apexRest, s.apexPhase1, s.apexPhase2, s.apexRest};
    for (int i = 0; i <= 4000; ++i) {
        const double t = i / 4000.0;
        const int piece = t <= keys[1] ? 0 : (t <= keys[2] ? 1 : 2);
        const CurlParams p = curlAt(t, s);
        EXPECT_GE(p.theta, std::min(thetas[piece], thetas[piece + 1]) - 1e-12) << "t=" << t;
        EXPECT_LE(p.theta, std::max(thetas[piece], thetas[piece + 1]) + 1e-12) << "t=" << t;
        EXPECT_GE(p.apexY, std::min(apexes[piece], apexes[piece + 1]) - 1e-12) << "t=" << t;
        EXPECT_LE(p.apexY, std::max(apexes[piece], apexes[piece + 1]) + 1e-12) << "t=" << t;
    }
}
