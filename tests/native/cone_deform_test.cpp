// Native (GoogleTest via CTest) tests of the cone deformation: the eight invariants and the parameter
// guards of docs/cone-curl-math.md, held over the whole schedule and a dense page grid.
#include "test_support.hpp"
#include "cone_deform.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

namespace {

using conecurl::coneBeta;
using conecurl::curlAt;
using conecurl::curlNormalAnalytic;
using conecurl::curlNormalFiniteDifference;
using conecurl::CurlParams;
using conecurl::curlPoint;
using conecurl::deformOntoCone;
using conecurl::kApexCeiling;
using conecurl::kThetaFloor;
using conecurl::rotateAboutSpine;
using conecurl::sanitize;
using glm::dvec2;
using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kW = 0.8;  // Nuon's page, 1 unit tall: the schedule's defaults assume it
constexpr double kH = 1.0;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Sample {
    double t;
    CurlParams p;
};

// The schedule every 0.001 of the turn (end points included) plus both sides of each phase boundary.
const std::vector<Sample>& schedule() {
    static const std::vector<Sample> samples = [] {
        std::vector<Sample> s;
        for (int i = 0; i <= 1000; ++i) s.push_back({i / 1000.0, curlAt(i / 1000.0)});
        for (double t : {0.15 - 1e-9, 0.15 + 1e-9, 0.4 - 1e-9, 0.4 + 1e-9}) s.push_back({t, curlAt(t)});
        return s;
    }();
    return samples;
}

// The page on a 41 x 51 lattice, step 0.02: its border rows and columns are the four edges and hold
// the four corners exactly. The dense sweeps (schedule x lattice, 2.1 million points) use it.
constexpr int kCols = 40;
constexpr int kRows = 50;
dvec2 latticePoint(int i, int j) { return {kW * i / kCols, kH * j / kRows}; }

const std::vector<dvec2>& lattice() {
    static const std::vector<dvec2> points = [] {
        std::vector<dvec2> p;
        for (int j = 0; j <= kRows; ++j)
            for (int i = 0; i <= kCols; ++i) p.push_back(latticePoint(i, j));
        return p;
    }();
    return points;
}

// The lattice plus the four edges four times finer (step 0.005), for the cheaper checks.
const std::vector<dvec2>& pagePoints() {
    static const std::vector<dvec2> points = [] {
        std::vector<dvec2> p = lattice();
        for (int i = 0; i <= 4 * kCols; ++i) {
            p.push_back({kW * i / (4 * kCols), 0.0});
            p.push_back({kW * i / (4 * kCols), kH});
        }
        for (int j = 0; j <= 4 * kRows; ++j) {
            p.push_back({0.0, kH * j / (4 * kRows)});
            p.push_back({kW, kH * j / (4 * kRows)});
        }
        return p;
    }();
    return points;
}

bool finite(dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string num(double x) {
    std::ostringstream os;
    os << x;
    return os.str();
}

using conecurl::testing::str;

// The largest error seen and where; NaN is kept once seen (it is the worst of all).
struct Worst {
    double value = 0.0;
    double t = kNaN;
    dvec2 q{kNaN, kNaN};
    void take(double v, double atT, dvec2 atQ) {
        if (std::isnan(value)) return;
        if (!(v <= value)) {
            value = v;
            t = atT;
            q = atQ;
        }
    }
    void merge(const Worst& o) { take(o.value, o.t, o.q); }
    std::string where() const {
        std::ostringstream os;
        os.precision(17);
        os << value << " at t = " << t << ", page point (" << q.x << ", " << q.y << ")";
        return os.str();
    }
    // Shown in the test log so a run states the measured error, not only pass/fail.
    void report(const char* what) const { std::printf("[ measured ] %s: %s\n", what, where().c_str()); }
};

// Counts non-finite outputs and remembers the first.
struct NonFinite {
    long count = 0;
    std::string first;
    void check(dvec3 v, double t, dvec2 q, const char* what) {
        if (finite(v) || count++ > 0) return;
        std::ostringstream os;
        os.precision(17);
        os << what << " at t = " << t << ", q = (" << q.x << ", " << q.y << "): " << str(v);
        first = os.str();
    }
    void merge(const NonFinite& o) {
        if (count == 0) first = o.first;
        count += o.count;
    }
};

// The dense sweeps evaluate the map some 25 million times. The map is a pure function, so the
// schedule's samples (every `stride`-th) are dealt round-robin to the hardware threads, each with its
// own accumulator (a struct with merge()), to keep the suite within a few seconds. The maxima do not
// depend on the order.
template <class Acc, class Body>
Acc overSchedule(Body body, size_t stride = 1) {
    const std::vector<Sample>& samples = schedule();
    const unsigned n = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
    std::vector<Acc> accs(n);
    std::vector<std::thread> threads;
    for (unsigned k = 0; k < n; ++k) {
        threads.emplace_back([&, k] {
            for (size_t i = k * stride; i < samples.size(); i += n * stride) body(samples[i], accs[k]);
        });
    }
    for (std::thread& th : threads) th.join();
    for (unsigned k = 1; k < n; ++k) accs[0].merge(accs[k]);
    return accs[0];
}

// Distance from the flat point to the apex (0, Ay): the invariant radius of invariant 1.
double apexRadius(dvec2 q, double apexY) { return std::hypot(q.x, q.y - apexY); }

// ---------------------------------------------------------------------------------------------
// Invariant 1: |T - A| = R, before and after the rotation (the spine axis passes through A).
// The sweep also says that positions are finite everywhere.

TEST(ConeDeform, PositionsAreFiniteAndKeepTheirFlatDistanceFromTheApex) {
    struct Acc {
        Worst before, after;
        NonFinite bad;
        void merge(const Acc& o) { before.merge(o.before), after.merge(o.after), bad.merge(o.bad); }
    };
    const Acc acc = overSchedule<Acc>([](const Sample& s, Acc& a) {
        const dvec3 A{0.0, s.p.apexY, 0.0};
        for (dvec2 q : lattice()) {
            const dvec3 v = deformOntoCone(q, s.p);
            const dvec3 w = curlPoint(q, s.p);
            a.bad.check(v, s.t, q, "deformOntoCone");
            a.bad.check(w, s.t, q, "curlPoint");
            const double R = apexRadius(q, s.p.apexY);
            a.before.take(std::abs(glm::length(v - A) - R), s.t, q);
            a.after.take(std::abs(glm::length(w - A) - R), s.t, q);
        }
    });
    acc.before.report("| |deformOntoCone - A| - R |");
    acc.after.report("| |curlPoint - A| - R |");
    EXPECT_EQ(acc.bad.count, 0) << "first: " << acc.bad.first;
    // R <= hypot(0.8, 16) ~ 16, whose ulp is 3.6e-15; the map and the norm take a dozen roundings.
    // 1e-13 is ~30 ulp of R and four orders below 1e-9.
    EXPECT_LE(acc.before.value, 1e-13) << acc.before.where();
    EXPECT_LE(acc.after.value, 1e-13) << acc.after.where();
}

// ---------------------------------------------------------------------------------------------
// Invariant 2 (isometry, E = G = 1, F = 0) and invariant 8 (unit normals perpendicular to both
// tangents; analytic = finite-difference normal), in one sweep because they share the tangents:
// the four extra map evaluations per point are the bulk of this suite's run time.

TEST(ConeDeform, IsAnIsometryAndBothNormalsAreUnitPerpendicularToTangentsAndAgree) {
    // Central differences with h = 1e-5: truncation h^2/6 |X'''|, |X'''| <~ 1/r^2 ~ 10 (tightest cone
    // radius r = R sin(theta) ~ 0.35, at t = 0.15) -> ~2e-10; rounding ~1e-16 / h ~ 1e-11. So E, G,
    // F carry up to ~4e-10: 1e-8 leaves margin yet rejects any real stretch (1e-8 strain is 0.01 um
    // on a 1 m page). The tangents of curlPoint are these differences rotated by rho (curlPoint is
    // rotateAboutSpine(deformOntoCone(q), rho) and a rotation is linear): n . T then errs ~1e-9 -> 1e-8.
    constexpr double h = 1e-5;
    constexpr double delta = 1e-6;
    struct Acc {
        Worst e, g, f, unitA, unitFd, perpA, perpFd, agree;
        NonFinite bad;
        void merge(const Acc& o) {
            e.merge(o.e), g.merge(o.g), f.merge(o.f), unitA.merge(o.unitA), unitFd.merge(o.unitFd);
            perpA.merge(o.perpA), perpFd.merge(o.perpFd), agree.merge(o.agree), bad.merge(o.bad);
        }
    };
    const Acc acc = overSchedule<Acc>([](const Sample& s, Acc& a) {
        for (dvec2 q : lattice()) {
            const dvec3 Xx =
                (deformOntoCone({q.x + h, q.y}, s.p) - deformOntoCone({q.x - h, q.y}, s.p)) / (2.0 * h);
            const dvec3 Xy =
                (deformOntoCone({q.x, q.y + h}, s.p) - deformOntoCone({q.x, q.y - h}, s.p)) / (2.0 * h);
            a.e.take(std::abs(glm::dot(Xx, Xx) - 1.0), s.t, q);
            a.g.take(std::abs(glm::dot(Xy, Xy) - 1.0), s.t, q);
            a.f.take(std::abs(glm::dot(Xx, Xy)), s.t, q);

            const dvec3 Tx = glm::normalize(rotateAboutSpine(Xx, s.p.rho));
            const dvec3 Ty = glm::normalize(rotateAboutSpine(Xy, s.p.rho));
            const dvec3 nA = curlNormalAnalytic(q, s.p);
            const dvec3 nFd = curlNormalFiniteDifference(q, s.p, delta);
            a.bad.check(nA, s.t, q, "curlNormalAnalytic");
            a.bad.check(nFd, s.t, q, "curlNormalFiniteDifference(1e-6)");
            a.unitA.take(std::abs(glm::length(nA) - 1.0), s.t, q);
            a.unitFd.take(std::abs(glm::length(nFd) - 1.0), s.t, q);
            a.perpA.take(std::max(std::abs(glm::dot(nA, Tx)), std::abs(glm::dot(nA, Ty))), s.t, q);
            a.perpFd.take(std::max(std::abs(glm::dot(nFd, Tx)), std::abs(glm::dot(nFd, Ty))), s.t, q);
            a.agree.take(glm::length(nA - nFd), s.t, q);
        }
    });
    acc.e.report("|E - 1|");
    acc.g.report("|G - 1|");
    acc.f.report("|F|");
    acc.unitA.report("| |n_analytic| - 1 |");
    acc.unitFd.report("| |n_fd(1e-6)| - 1 |");
    acc.perpA.report("max |n_analytic . tangent|");
    acc.perpFd.report("max |n_fd(1e-6) . tangent|");
    acc.agree.report("|n_analytic - n_fd(1e-6)|");
    EXPECT_EQ(acc.bad.count, 0) << "first: " << acc.bad.first;
    EXPECT_LE(acc.e.value, 1e-8) << acc.e.where();
    EXPECT_LE(acc.g.value, 1e-8) << acc.g.where();
    EXPECT_LE(acc.f.value, 1e-8) << acc.f.where();
    // The closed form is unit exactly and the paper's normal is normalize()d: only rounding is left.
    EXPECT_LE(acc.unitA.value, 1e-14) << acc.unitA.where();
    EXPECT_LE(acc.unitFd.value, 1e-14) << acc.unitFd.where();
    EXPECT_LE(acc.perpA.value, 1e-8) << acc.perpA.where();
    // A forward difference tilts the normal by ~delta/2 |X''|, |X''| <= 1/r ~ 3: ~1.5e-6 (rounding
    // 1e-16 / delta = 1e-10 is negligible); asserted at 1e-5.
    EXPECT_LE(acc.perpFd.value, 1e-5) << acc.perpFd.where();
    EXPECT_LE(acc.agree.value, 1e-5) << acc.agree.where();
}

// The paper's own step (about 1e-3 of the page) is coarser: its tilt ~delta/2 |X''| ~ 1.5e-3.
TEST(ConeDeform, PaperStepFiniteDifferenceNormalAgreesWithAnalyticToAFewThousandths) {
    struct Acc {
        Worst paper;
        NonFinite bad;
        void merge(const Acc& o) { paper.merge(o.paper), bad.merge(o.bad); }
    };
    const Acc acc = overSchedule<Acc>([](const Sample& s, Acc& a) {
        for (dvec2 q : lattice()) {
            const dvec3 nFd = curlNormalFiniteDifference(q, s.p, 1e-3);
            a.bad.check(nFd, s.t, q, "curlNormalFiniteDifference(1e-3)");
            a.paper.take(glm::length(curlNormalAnalytic(q, s.p) - nFd), s.t, q);
        }
    });
    acc.paper.report("|n_analytic - n_fd(1e-3)|");
    EXPECT_EQ(acc.bad.count, 0) << "first: " << acc.bad.first;
    EXPECT_LE(acc.paper.value, 5e-3) << acc.paper.where();
    // It is a real discretisation error, not rounding: the comparison is sharp enough to see one.
    EXPECT_GT(acc.paper.value, 1e-4);
}

// A curve's chord is never longer than its arc; the flat segment between neighbouring lattice points
// maps to a curve of the same length, so the 3D distance can only shrink. Neighbours across, up and
// along both diagonals.
TEST(ConeDeform, NeverStretchesChordsBetweenNeighbouringGridPoints) {
    struct Acc {
        Worst stretch;
        double minRatio = 1.0;
        void merge(const Acc& o) { stretch.merge(o.stretch), minRatio = std::min(minRatio, o.minRatio); }
    };
    const Acc acc = overSchedule<Acc>([](const Sample& s, Acc& a) {
        const int di[] = {1, 0, 1, 1};
        const int dj[] = {0, 1, 1, -1};
        std::vector<dvec3> X((kCols + 1) * (kRows + 1));
        for (int j = 0; j <= kRows; ++j)
            for (int i = 0; i <= kCols; ++i) X[j * (kCols + 1) + i] = curlPoint(latticePoint(i, j), s.p);
        for (int j = 0; j <= kRows; ++j) {
            for (int i = 0; i <= kCols; ++i) {
                for (int k = 0; k < 4; ++k) {
                    const int i2 = i + di[k];
                    const int j2 = j + dj[k];
                    if (i2 > kCols || j2 < 0 || j2 > kRows) continue;
                    const double flat = glm::length(latticePoint(i2, j2) - latticePoint(i, j));
                    const double chord = glm::length(X[j2 * (kCols + 1) + i2] - X[j * (kCols + 1) + i]);
                    a.stretch.take(chord - flat, s.t, latticePoint(i, j));
                    a.minRatio = std::min(a.minRatio, chord / flat);
                }
            }
        }
    });
    acc.stretch.report("max(chord - flat)");
    std::printf("[ measured ] min chord / flat over the schedule: %.9f\n", acc.minRatio);
    // Differences of points of size ~1 carry ~1e-16 of rounding each; 1e-14 is that with margin.
    EXPECT_LE(acc.stretch.value, 1e-14) << acc.stretch.where();
    // The test sees real bending: a chord of 0.02-0.028 across curvature ~3 is ~1e-4 shorter.
    EXPECT_LT(acc.minRatio, 1.0 - 1e-5);
}

// ---------------------------------------------------------------------------------------------
// Invariant 3: the spine is fixed.

TEST(ConeDeform, KeepsTheSpineFixedForEveryTimeAndHeight) {
    struct Acc {
        Worst err;
        void merge(const Acc& o) { err.merge(o.err); }
    };
    const Acc acc = overSchedule<Acc>([](const Sample& s, Acc& a) {
        for (int j = 0; j <= 1000; ++j) {  // every 0.001 up the spine
            const dvec2 q{0.0, kH * j / 1000.0};
            a.err.take(glm::length(curlPoint(q, s.p) - dvec3{0.0, q.y, 0.0}), s.t, q);
        }
    });
    acc.err.report("|curlPoint(0, y) - (0, y, 0)|");
    // beta = 0 there, so x and z are exactly 0; y = y (y - 2 Ay) / (y - 2 Ay) takes 3 roundings.
    EXPECT_LE(acc.err.value, 1e-15) << acc.err.where();
}

// ---------------------------------------------------------------------------------------------
// Invariant 4: theta = pi/2 is the identity before rotation; rotation keeps y and sqrt(x^2 + z^2).

TEST(ConeDeform, FlatConeIsTheIdentityBeforeRotation) {
    // Apexes of the schedule's range and a far one. A naive R + Ay at Ay = -1e6 would be off by 1e-10.
    Worst err;
    for (double apexY : {-15.0, -3.5, -2.5, -1.0, -0.1, -1e6}) {
        const CurlParams p{kPi / 2.0, apexY, 0.0};
        for (dvec2 q : pagePoints())
            err.take(glm::length(deformOntoCone(q, p) - dvec3{q.x, q.y, 0.0}), apexY, q);
    }
    err.report("|deform_{theta=pi/2}(q) - (x, y, 0)| (t column = apexY)");
    // A few roundings on coordinates <= 1: 1e-14.
    EXPECT_LE(err.value, 1e-14) << err.where();

    // With the apex at the guard ceiling (1e-4 below the bottom edge), x / R comes within ~1e-8 of 1
    // at the bottom corners, where asin has slope 1 / sqrt(1 - (x/R)^2) ~ 1e4: the rounding of x / R
    // (1.1e-16) becomes ~1e-12 in beta and in the position. That is the conditioning of the paper's
    // asin(x / R) itself, not a defect of the code; 1e-11 bounds it with margin.
    Worst ceiling;
    const CurlParams p{kPi / 2.0, kApexCeiling, 0.0};
    for (dvec2 q : pagePoints())
        ceiling.take(glm::length(deformOntoCone(q, p) - dvec3{q.x, q.y, 0.0}), 0.0, q);
    ceiling.report("same with apexY = kApexCeiling");
    EXPECT_LE(ceiling.value, 1e-11) << ceiling.where();
}

TEST(ConeDeform, RotationAboutSpineKeepsHeightAndDistanceFromSpine) {
    Worst dy, dr, roundTrip, composition;
    for (int i = 0; i <= 100; ++i) {  // every 0.01 of the turn: rotateAboutSpine does not depend on t
        const Sample s{i / 100.0, curlAt(i / 100.0)};
        for (dvec2 q : lattice()) {
            const dvec3 v = deformOntoCone(q, s.p);
            // curlPoint is exactly this composition (the isometry test relies on it).
            composition.take(glm::length(curlPoint(q, s.p) - rotateAboutSpine(v, s.p.rho)), s.t, q);
            for (double rho : {s.p.rho, 1.0, -2.0, 7.0, kPi}) {
                const dvec3 w = rotateAboutSpine(v, rho);
                dy.take(std::abs(w.y - v.y), s.t, q);
                dr.take(std::abs(std::hypot(w.x, w.z) - std::hypot(v.x, v.z)), s.t, q);
                roundTrip.take(glm::length(rotateAboutSpine(w, -rho) - v), s.t, q);
            }
        }
    }
    dr.report("| |rotated xz| - |xz| |");
    EXPECT_EQ(composition.value, 0.0) << composition.where();
    EXPECT_EQ(dy.value, 0.0) << dy.where();  // y is copied, not computed
    // cos^2 + sin^2 = 1 to ~2 ulp, on |xz| <= 1: 1e-15.
    EXPECT_LE(dr.value, 1e-15) << dr.where();
    EXPECT_LE(roundTrip.value, 1e-15) << roundTrip.where();
    // Direction: positive rho lifts +x towards +z (a right-hand page turning to the left, viewer on +z).
    const dvec3 quarter = rotateAboutSpine({1.0, 0.5, 0.0}, kPi / 2.0);
    EXPECT_NEAR(quarter.x, 0.0, 1e-15);
    EXPECT_EQ(quarter.y, 0.5);
    EXPECT_NEAR(quarter.z, 1.0, 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Invariant 5: before the rotation the page curls up, towards the viewer (z >= 0).

TEST(ConeDeform, StaysOnTheViewerSideBeforeRotation) {
    struct Acc {
        Worst below;
        double maxZ = 0.0;
        void merge(const Acc& o) { below.merge(o.below), maxZ = std::max(maxZ, o.maxZ); }
    };
    const Acc acc = overSchedule<Acc>([](const Sample& s, Acc& a) {
        for (dvec2 q : lattice()) {
            const double z = deformOntoCone(q, s.p).z;
            a.below.take(-z, s.t, q);
            a.maxZ = std::max(a.maxZ, z);
        }
    });
    acc.below.report("max(-z) before rotation (0: never below)");
    // z = r (1 - cos beta) cos theta is a product of non-negative factors: allowing -1e-12 is generous.
    EXPECT_LE(acc.below.value, 1e-12) << acc.below.where();
    EXPECT_GT(acc.maxZ, 0.1);  // the test sees a real curl, not a flat page
}

// ---------------------------------------------------------------------------------------------
// Invariant 6: t = 0 is the page resting right (x, y, 0), t = 1 resting left (-x, y, ~0).

TEST(ConeDeform, RestsFlatOnTheRightAtStartAndFlatOnTheLeftAtEnd) {
    Worst start, end;
    for (dvec2 q : pagePoints()) {
        start.take(glm::length(curlPoint(q, curlAt(0.0)) - dvec3{q.x, q.y, 0.0}), 0.0, q);
        end.take(glm::length(curlPoint(q, curlAt(1.0)) - dvec3{-q.x, q.y, 0.0}), 1.0, q);
    }
    start.report("|T(t=0) - (x, y, 0)|");
    end.report("|T(t=1) - (-x, y, 0)|");
    // Exact maths; a few roundings plus sin(pi) = 1.2e-16 (the double pi is not pi) times |x| <= 0.8.
    EXPECT_LE(start.value, 1e-14) << start.where();
    EXPECT_LE(end.value, 1e-14) << end.where();
}

// ---------------------------------------------------------------------------------------------
// Invariant 7: beta stays below pi (the page never passes through itself); its maximum, ~2.23 rad,
// is at the end of phase 1 (t = 0.15) at the bottom free corner (0.8, 0).

TEST(ConeDeform, ConeBetaStaysBelowPiAndPeaksAtPhase1EndAtBottomCorner) {
    struct Acc {
        Worst maxBeta, formula;
        void merge(const Acc& o) { maxBeta.merge(o.maxBeta), formula.merge(o.formula); }
    };
    const Acc acc = overSchedule<Acc>([](const Sample& s, Acc& a) {
        const double sinTheta = std::sin(s.p.theta);
        for (dvec2 q : pagePoints()) {
            const double b = coneBeta(q, s.p);
            a.maxBeta.take(std::abs(b), s.t, q);
            // beta as the paper writes it, asin(x / R) / sin(theta): no clamp may be active anywhere on the schedule.
            a.formula.take(std::abs(b - std::asin(q.x / apexRadius(q, s.p.apexY)) / sinTheta), s.t, q);
        }
    });
    acc.maxBeta.report("max |beta|");
    acc.formula.report("|coneBeta - asin(x/R)/sin(theta)|");
    EXPECT_LT(acc.maxBeta.value, kPi);
    EXPECT_GT(acc.maxBeta.value, 2.1);
    EXPECT_LT(acc.maxBeta.value, 2.35);
    // asin(0.8 / hypot(0.8, 2.5)) / sin(8 deg) = 2.2253...
    EXPECT_NEAR(acc.maxBeta.value, std::asin(0.8 / std::hypot(0.8, 2.5)) / std::sin(8.0 * kDeg), 1e-12);
    EXPECT_EQ(acc.maxBeta.t, 0.15);
    EXPECT_EQ(acc.maxBeta.q.x, kW);
    EXPECT_EQ(acc.maxBeta.q.y, 0.0);
    EXPECT_LE(acc.formula.value, 1e-14) << acc.formula.where();
}

// ---------------------------------------------------------------------------------------------
// Invariant 8, orientation: the front normal faces +z on the resting page and -z after the turn.

TEST(ConeDeform, FrontNormalFacesViewerWhenFlatAndAwayAfterTheTurn) {
    Worst flat, turned, turnedFd;
    const CurlParams flatCone{kPi / 2.0, -2.5, 0.0};
    for (dvec2 q : pagePoints()) {
        flat.take(glm::length(curlNormalAnalytic(q, curlAt(0.0)) - dvec3{0, 0, 1}), 0.0, q);
        flat.take(glm::length(curlNormalAnalytic(q, flatCone) - dvec3{0, 0, 1}), 0.0, q);
        // After the turn the front is the flat front rotated by pi about y: (0, 0, 1) -> (0, 0, -1),
        // so the back faces the viewer.
        turned.take(glm::length(curlNormalAnalytic(q, curlAt(1.0)) - dvec3{0, 0, -1}), 1.0, q);
        const dvec3 nFd = curlNormalFiniteDifference(q, curlAt(1.0), 1e-6);
        turnedFd.take(glm::length(nFd - dvec3{0, 0, -1}), 1.0, q);
    }
    flat.report("|n(flat) - (0,0,1)|");
    turned.report("|n(t=1) - (0,0,-1)|");
    turnedFd.report("|n_fd(t=1) - (0,0,-1)|");
    // cos(pi/2) and sin(pi) are ~1e-16 in double, not 0.
    EXPECT_LE(flat.value, 1e-14) << flat.where();
    EXPECT_LE(turned.value, 1e-14) << turned.where();
    EXPECT_LE(turnedFd.value, 1e-9) << turnedFd.where();  // flat page: only rounding / delta
}

// ---------------------------------------------------------------------------------------------
// The parameter guards of the doc (sanitize) and the points where naive formulas fail.

TEST(ConeDeformGuards, SanitizeMapsNaNParametersToFiniteValuesInDomain) {
    for (int mask = 1; mask < 8; ++mask) {
        const CurlParams raw{(mask & 1) ? kNaN : 0.3, (mask & 2) ? kNaN : -2.0, (mask & 4) ? kNaN : 1.0};
        const CurlParams p = sanitize(raw);
        SCOPED_TRACE("NaN mask " + std::to_string(mask));
        EXPECT_TRUE(std::isfinite(p.theta));
        EXPECT_TRUE(std::isfinite(p.apexY));
        EXPECT_TRUE(std::isfinite(p.rho));
        EXPECT_GE(p.theta, kThetaFloor);
        EXPECT_LE(p.theta, kPi / 2.0);
        EXPECT_LE(p.apexY, kApexCeiling);
        // A NaN angle becomes the resting value (flat, right); values that were not NaN pass through.
        EXPECT_EQ(p.theta, (mask & 1) ? kPi / 2.0 : 0.3);
        EXPECT_EQ(p.rho, (mask & 4) ? 0.0 : 1.0);
        EXPECT_EQ(p.apexY, (mask & 2) ? conecurl::CurlSchedule{}.apexRest : -2.0);
        for (dvec2 q : pagePoints()) {
            ASSERT_TRUE(finite(curlPoint(q, raw))) << q.x << ", " << q.y;
            ASSERT_TRUE(finite(curlNormalAnalytic(q, raw))) << q.x << ", " << q.y;
        }
    }
}

TEST(ConeDeformGuards, SanitizeClampsThetaToFloorAndHalfPiAndApexToCeiling) {
    for (double theta : {-kInf, -1.0, -1e-9, 0.0, 1e-9, kThetaFloor / 2.0})
        EXPECT_EQ(sanitize({theta, -2.0, 0.0}).theta, kThetaFloor) << "theta = " << theta;
    for (double theta : {kPi / 2.0 + 1e-12, 2.0, 100.0, kInf})
        EXPECT_EQ(sanitize({theta, -2.0, 0.0}).theta, kPi / 2.0) << "theta = " << theta;
    for (double theta : {kThetaFloor, 0.1, 1.0, kPi / 2.0})
        EXPECT_EQ(sanitize({theta, -2.0, 0.0}).theta, theta) << "theta = " << theta;
    for (double apexY : {0.0, -0.0, 0.5, 1e-300, kApexCeiling / 2.0, kInf})
        EXPECT_EQ(sanitize({0.1, apexY, 0.0}).apexY, kApexCeiling) << "apexY = " << apexY;
    for (double apexY : {kApexCeiling, -1.0, -15.0, -1e6})
        EXPECT_EQ(sanitize({0.1, apexY, 0.0}).apexY, apexY) << "apexY = " << apexY;
    for (double rho : {-7.0, 0.0, 1.0, kPi, 10.0}) EXPECT_EQ(sanitize({0.1, -2.0, rho}).rho, rho);
    EXPECT_EQ(sanitize({0.1, -2.0, kInf}).rho, 0.0);
    EXPECT_EQ(sanitize({0.1, -2.0, -kInf}).rho, 0.0);
}

// Every lattice point (edges and corners included) under the given degenerate thetas and apexes, with
// and without a rotation: positions and both normals (the paper's step and a fine one) must be
// finite, and beta within [-pi, pi].
void expectFiniteEverywhere(const std::vector<double>& thetas, const std::vector<double>& apexes) {
    long bad = 0;
    std::string first;
    double maxBeta = 0.0;
    for (double theta : thetas) {
        for (double apexY : apexes) {
            for (double rho : {0.0, 2.0}) {
                const CurlParams p{theta, apexY, rho};
                for (dvec2 q : lattice()) {
                    maxBeta = std::max(maxBeta, std::abs(coneBeta(q, p)));
                    const dvec3 outs[] = {deformOntoCone(q, p), curlPoint(q, p), curlNormalAnalytic(q, p),
                                          curlNormalFiniteDifference(q, p, 1e-3),
                                          curlNormalFiniteDifference(q, p, 1e-6)};
                    for (const dvec3& v : outs) {
                        if (!finite(v) && bad++ == 0) {
                            std::ostringstream os;
                            os << "theta = " << theta << ", apexY = " << apexY << ", rho = " << rho
                               << ", q = (" << q.x << ", " << q.y << "): " << str(v);
                            first = os.str();
                        }
                    }
                }
            }
        }
    }
    EXPECT_EQ(bad, 0) << "first non-finite: " << first;
    EXPECT_LE(maxBeta, kPi);
}

TEST(ConeDeformGuards, TinyZeroOrNegativeThetaGivesFiniteOutput) {
    expectFiniteEverywhere({0.0, 1e-9, 1e-300, -1e-9, -1.0, -kInf, kThetaFloor},
                           {-15.0, -2.5, -1e-4, 0.0, 0.5});
}

TEST(ConeDeformGuards, ApexAtOrAboveThePageGivesFiniteOutput) {
    expectFiniteEverywhere({8.0 * kDeg, 6.0 * kDeg, 45.0 * kDeg, kPi / 2.0, kThetaFloor},
                           {0.0, -0.0, 1e-300, 1e-6, 0.5, 2.0, kInf});
    // And the map is still the cone map about the clamped apex: the apex distance holds.
    Worst err;
    for (double apexY : {0.0, 0.5}) {
        const CurlParams p{8.0 * kDeg, apexY, 0.7};
        for (dvec2 q : pagePoints()) {
            const double R = apexRadius(q, kApexCeiling);
            err.take(std::abs(glm::length(curlPoint(q, p) - dvec3{0.0, kApexCeiling, 0.0}) - R), apexY, q);
        }
    }
    EXPECT_LE(err.value, 1e-13) << err.where();
}

// An apex at -infinity, or below about -DBL_MAX / 2, would overflow q.y (q.y - 2 Ay) and R - Ay into
// NaN everywhere; sanitize() floors the apex at kApexFloor so the output stays finite.
TEST(ConeDeformGuards, InfiniteOrHugeNegativeApexGivesFiniteOutput) {
    for (double apexY : {-1e300, -std::numeric_limits<double>::max(), -kInf}) {
        SCOPED_TRACE("apexY = " + num(apexY));
        EXPECT_TRUE(std::isfinite(sanitize({0.1, apexY, 0.0}).apexY));
        long bad = 0;
        std::string first;
        for (double theta : {8.0 * kDeg, kPi / 2.0}) {
            const CurlParams p{theta, apexY, 1.0};
            for (dvec2 q : lattice()) {
                for (const dvec3& v : {curlPoint(q, p), curlNormalAnalytic(q, p)}) {
                    if (!finite(v) && bad++ == 0)
                        first = "theta = " + num(theta) + ", q = (" + num(q.x) + ", " + num(q.y) +
                                "): " + str(v);
                }
            }
        }
        EXPECT_EQ(bad, 0) << "first non-finite: " << first;
    }
}

// Near the apex x / R can round to (or past) 1 and R can be 0: asin and the division must not blow up.
TEST(ConeDeformGuards, PointsAtTheApexRegionGiveFiniteOutput) {
    const double a = kApexCeiling;
    const dvec2 points[] = {
        {0.0, a},                                    // the apex itself: R = 0
        {1e-300, a}, {5e-324, a}, {-1e-300, a},      // x tiny, R tiny
        {1e-12, a}, {0.8, a}, {-0.8, a},              // at the apex height: x / R = +-1 exactly
        {1e-300, 0.0}, {5e-324, 0.0}, {1e-12, 0.0},  // x tiny relative to R on the bottom edge
        {1e5, 0.0}, {1e8, 0.0}, {-1e8, 0.0},         // x / R rounds to 1 (R = x (1 + <= 5e-19))
        {0.8, a + 1e-20}, {1e-10, a + 1e-20},
    };
    for (double theta : {8.0 * kDeg, 6.0 * kDeg, kThetaFloor, 0.0, kPi / 2.0}) {
        for (double rho : {0.0, 1.0}) {
            const CurlParams p{theta, a, rho};
            for (dvec2 q : points) {
                SCOPED_TRACE("theta = " + num(theta) + ", q = (" + num(q.x) + ", " + num(q.y) + ")");
                const double b = coneBeta(q, p);
                EXPECT_TRUE(std::isfinite(b));
                EXPECT_LE(std::abs(b), kPi);
                EXPECT_TRUE(finite(deformOntoCone(q, p))) << str(deformOntoCone(q, p));
                EXPECT_TRUE(finite(curlPoint(q, p))) << str(curlPoint(q, p));
                EXPECT_TRUE(finite(curlNormalAnalytic(q, p))) << str(curlNormalAnalytic(q, p));
                EXPECT_LE(std::abs(glm::length(curlNormalAnalytic(q, p)) - 1.0), 1e-14);
            }
        }
    }
    // At the apex height the point lies on the ruling x / R = 1 exactly: beta = (pi/2) / sin(theta).
    const CurlParams p{kPi / 2.0, a, 0.0};
    EXPECT_NEAR(coneBeta({0.8, a}, p), kPi / 2.0, 1e-15);
    EXPECT_NEAR(coneBeta({1e8, 0.0}, p), kPi / 2.0, 1e-6);
}

// A far apex (Ay = -1e6, R ~ 1e6): R + Ay computed naively loses ~1e-10 (ulp of 1e6); the
// (R^2 - Ay^2) / (R - Ay) form must keep the page accurate far below that.
long double referenceY(long double x, long double y, long double theta, long double apexY) {
    // The paper's formula for v.y, literally, in extended precision (64-bit mantissa on x86-64:
    // rounding R + Ay costs ulp(1e6) / 2 = 3e-14; with 1 - cos(beta) scaled by R the reference is good
    // to ~1e-13, so 1e-12 is asserted, a hundred times below the naive form's 1e-10).
    const long double R = std::sqrt(x * x + (y - apexY) * (y - apexY));
    const long double beta = std::asin(x / R) / std::sin(theta);
    const long double r = R * std::sin(theta);
    return R + apexY - r * (1.0L - std::cos(beta)) * std::sin(theta);
}

TEST(ConeDeformGuards, FarApexStaysFiniteAndAccurate) {
    if (std::numeric_limits<long double>::digits < 64) GTEST_SKIP() << "needs an extended long double";
    constexpr double apexY = -1e6;
    Worst yErr, apexRel, naiveErr;
    for (double theta : {6.0 * kDeg, 8.0 * kDeg, 30.0 * kDeg, 60.0 * kDeg, 89.0 * kDeg, kPi / 2.0}) {
        const CurlParams p{theta, apexY, 0.0};
        for (dvec2 q : pagePoints()) {
            const dvec3 v = deformOntoCone(q, p);
            ASSERT_TRUE(finite(v)) << "q = (" << q.x << ", " << q.y << "): " << str(v);
            yErr.take(std::abs(v.y - static_cast<double>(referenceY(q.x, q.y, theta, apexY))), theta, q);
            // Relative apex distance: the test's own |T - A| rounds at 1e6 scale.
            const double R = apexRadius(q, apexY);
            apexRel.take(std::abs(glm::length(v - dvec3{0.0, apexY, 0.0}) - R) / R, theta, q);
            // How far a naive double R + Ay would be: the reason for the rewritten form.
            const double sinT = std::sin(theta);
            const double naive = (R + apexY) - R * sinT * (1.0 - std::cos(coneBeta(q, p))) * sinT;
            naiveErr.take(std::abs(naive - static_cast<double>(referenceY(q.x, q.y, theta, apexY))), theta,
                          q);
        }
    }
    yErr.report("|v.y - extended-precision reference| at Ay = -1e6 (t column = theta)");
    naiveErr.report("same for a naive double R + Ay (not asserted small)");
    EXPECT_LE(yErr.value, 1e-12) << yErr.where();
    EXPECT_LE(apexRel.value, 1e-15) << apexRel.where();
    // The check is sharp enough to catch the naive form.
    EXPECT_GT(naiveErr.value, 1e-12);
    // The spine stays fixed exactly even there.
    for (int j = 0; j <= 100; ++j) {
        const double y = j / 100.0;
        const dvec3 v = curlPoint({0.0, y}, CurlParams{8.0 * kDeg, apexY, 1.0});
        EXPECT_NEAR(v.y, y, 1e-15);
        EXPECT_EQ(v.x, 0.0);
        EXPECT_EQ(v.z, 0.0);
    }
}

}  // namespace
