// Native (GoogleTest via CTest) tests of the mesh resolution: the measured sag of the flat-triangle mesh
// behaves as theory says, and the chosen grid keeps it within half a pixel on a dense sweep of the turn.
#include "mesh_resolution.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "cone_deform.hpp"
#include "curl_schedule.hpp"
#include "page_grid.hpp"

namespace {

using conecurl::chooseGridResolution;
using conecurl::closedFormGridResolution;
using conecurl::CurlSchedule;
using conecurl::GridResolution;
using conecurl::makePageGrid;
using conecurl::measureMeshDeviation;
using conecurl::MeshDeviation;
using conecurl::PageGrid;

constexpr double kW = 0.8;  // Nuon's page, 1 unit tall: the schedule's defaults assume it
constexpr double kH = 1.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
const double kCot8Deg = 1.0 / std::tan(8.0 * 3.14159265358979323846 / 180.0);  // the tightest cone's theta

// Every 0.005 of the turn, both ends included, plus each phase boundary and both sides of it: the
// dense sweep the chooser's coarse verification (about a dozen times) is held against. i / 200.0 is
// the same double as the chooser's i / 10.0 and 0.15, so the dense set holds the coarse one.
std::vector<double> denseTimes() {
    std::vector<double> times;
    for (int i = 0; i <= 200; ++i) times.push_back(i / 200.0);
    for (double t : {0.15, 0.4, 0.15 - 1e-9, 0.15 + 1e-9, 0.4 - 1e-9, 0.4 + 1e-9}) times.push_back(t);
    return times;
}

// measureMeshDeviation over many times, the times dealt round-robin to the hardware threads (the
// measurement is a pure function; the maximum does not depend on the order).
MeshDeviation measureInParallel(const PageGrid& grid, double pageHeight, const std::vector<double>& times,
                                const CurlSchedule& schedule = CurlSchedule{}) {
    const unsigned n = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
    std::vector<MeshDeviation> parts(n, MeshDeviation{0.0, 0.0, 0.0, 0.0});
    std::vector<std::thread> threads;
    for (unsigned k = 0; k < n; ++k) {
        threads.emplace_back([&, k] {
            std::vector<double> mine;
            for (size_t i = k; i < times.size(); i += n) mine.push_back(times[i]);
            parts[k] = measureMeshDeviation(grid, schedule, pageHeight, mine);
        });
    }
    for (std::thread& th : threads) th.join();
    MeshDeviation worst = parts[0];
    for (const MeshDeviation& p : parts) {
        if (std::isnan(p.maxDistance) || p.maxDistance > worst.maxDistance) worst = p;
    }
    return worst;
}

PageGrid gridFor(double width, double height, int rows) {
    const int columns = std::max(4, static_cast<int>(std::lround(rows * width / height)));
    return makePageGrid(width, height, columns, rows);
}

std::string describe(const MeshDeviation& d) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.4g at t = %.4f, (x, y) = (%.4f, %.4f)", d.maxDistance, d.t, d.x, d.y);
    return buf;
}

// ---------------------------------------------------------------------------------------------
// The measurement

TEST(MeshResolution, DeviationVanishesOnTheFlatPageAtStartAndEndAndNotMidTurn) {
    const PageGrid grid = makePageGrid(kW, kH, 8, 10);
    for (double t : {0.0, 1.0}) {
        const MeshDeviation d = measureMeshDeviation(grid, CurlSchedule{}, kH, {t});
        EXPECT_LT(d.maxDistance, 1e-12) << "t = " << t << ": " << describe(d);
    }
    // A 10-row mesh over a cone of radius ~0.35 sags by ~1e-3; 1e-5 is far from both that and zero.
    for (double t : {0.05, 0.15, 0.3, 0.4, 0.7}) {
        const MeshDeviation d = measureMeshDeviation(grid, CurlSchedule{}, kH, {t});
        EXPECT_GT(d.maxDistance, 1e-5) << "t = " << t << ": " << describe(d);
        EXPECT_EQ(d.t, t);
    }
}

TEST(MeshResolution, EmptyTimesOrEmptyGridMeasureZero) {
    const MeshDeviation none = measureMeshDeviation(makePageGrid(kW, kH, 8, 10), CurlSchedule{}, kH, {});
    EXPECT_EQ(none.maxDistance, 0.0);
    const MeshDeviation empty = measureMeshDeviation(PageGrid{}, CurlSchedule{}, kH, {0.15, 0.4});
    EXPECT_EQ(empty.maxDistance, 0.0);
}

// The measurement restated from scratch: every triangle, every sample, with curlPoint itself (after
// the spine rotation, nothing shared between triangles). measureMeshDeviation measures shared edge
// midpoints once and works before the rotation (a rigid motion); it must give the same maximum.
TEST(MeshResolution, MatchesABruteForceMeasurementWithCurlPoint) {
    const double samples[][3] = {{0.5, 0.5, 0.0},    {0.0, 0.5, 0.5},    {0.5, 0.0, 0.5},
                                 {1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.5, 0.25, 0.25}, {0.25, 0.5, 0.25},
                                 {0.25, 0.25, 0.5}};
    for (const auto& [columns, rows] : {std::pair{7, 9}, std::pair{16, 20}}) {
        const PageGrid grid = makePageGrid(kW, kH, columns, rows);
        for (double t : {0.05, 0.15, 0.3, 0.4, 0.75}) {
            const conecurl::CurlParams p = conecurl::curlAt(t);
            double worst = 0.0;
            for (size_t k = 0; k < grid.indices.size(); k += 3) {
                glm::dvec2 q[3];
                for (int v = 0; v < 3; ++v) {
                    const size_t i = grid.indices[k + v];
                    q[v] = {grid.points[2 * i], grid.points[2 * i + 1]};
                }
                for (const auto& w : samples) {
                    glm::dvec2 at{0.0, 0.0};
                    glm::dvec3 onMesh{0.0, 0.0, 0.0};
                    for (int v = 0; v < 3; ++v) {
                        at += w[v] * q[v];
                        onMesh += w[v] * conecurl::curlPoint(q[v], p);
                    }
                    worst = std::max(worst, glm::distance(onMesh, conecurl::curlPoint(at, p)));
                }
            }
            const MeshDeviation d = measureMeshDeviation(grid, CurlSchedule{}, kH, {t});
            EXPECT_NEAR(d.maxDistance, worst, 1e-14 + 1e-9 * worst)
                << columns << " x " << rows << ", t = " << t << ": " << describe(d);
        }
    }
}

// Linear interpolation of a smooth surface is second order: halving the cell (rows and columns
// doubled) divides the sag by 4. A first-order error (a wrong barycentric match, a sample taken at
// the wrong page point) would give 2; a measurement blind to the sag would give ~1 or noise.
TEST(MeshResolution, DeviationShrinksAboutFourfoldWhenTheGridDoubles) {
    const std::vector<double> times = {0.1, 0.15, 0.25, 0.4, 0.6, 0.8};
    for (double t : times) {
        double previous = 0.0;
        for (int rows : {10, 20, 40, 80}) {
            const MeshDeviation d = measureMeshDeviation(gridFor(kW, kH, rows), CurlSchedule{}, kH, {t});
            if (rows > 10) {
                const double ratio = previous / d.maxDistance;
                EXPECT_GE(ratio, 3.0) << "t = " << t << ", rows " << rows / 2 << " -> " << rows;
                EXPECT_LE(ratio, 5.0) << "t = " << t << ", rows " << rows / 2 << " -> " << rows;
            }
            previous = d.maxDistance;
        }
    }
}

// The closed form's premise: the sag is worst at the bottom of the spine, nearest the apex, where the
// cone is tightest, and at the end of phase 1 (8 deg, apex at -2.5: the smallest cot(theta) radius).
// Its size there is cot(theta) / (8 |Ay|) * dx^2 to within a percent.
TEST(MeshResolution, WorstSagSitsAtTheBottomOfTheSpineAtPhase1EndAndMatchesTheClosedForm) {
    const int rows = 40;
    const PageGrid grid = gridFor(kW, kH, rows);
    const double dx = kW / grid.columns;
    const MeshDeviation d = measureInParallel(grid, kH, denseTimes());
    EXPECT_NEAR(d.t, 0.15, 0.0051) << describe(d);
    EXPECT_LE(d.x, dx) << describe(d);
    EXPECT_LE(d.y, kH / rows) << describe(d);
    const double predicted = kCot8Deg / (8.0 * 2.5) * dx * dx;
    EXPECT_NEAR(d.maxDistance / predicted, 1.0, 0.01) << describe(d) << "; closed form " << predicted;
}

// ---------------------------------------------------------------------------------------------
// The choice

struct Scale {
    double width, height, pixelsPerUnit, magnification, maxErrorPixels;
};

std::string describe(const Scale& s) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "page %g x %g, %g px/unit x %g, budget %g px", s.width, s.height,
                  s.pixelsPerUnit, s.magnification, s.maxErrorPixels);
    return buf;
}

// The chosen grid is held against the dense sweep (0.005 steps; the chooser's own uniform step is 0.2). It must meet the budget there. And it must not be wasteful: one row fewer measures above the
// budget, or (the honest allowance for a coarse check that could in principle be fooled in the
// other direction) at least within 15% of it.
TEST(MeshResolution, ChosenGridMeetsTheBudgetOnADenseSweepAndOneRowFewerDoesNotOrBarely) {
    std::vector<Scale> scales;
    for (double ppu : {300.0, 800.0, 1600.0, 3000.0}) {
        for (double mag : {1.0, 1.6}) scales.push_back({kW, kH, ppu, mag, 0.5});
    }
    scales.push_back({kW, kH, 1600.0, 1.0, 0.25});    // a tighter budget
    scales.push_back({1.5, 2.0, 1000.0, 1.3, 0.5});   // a taller page: the apex scales with the height
    scales.push_back({1.1, 1.0, 1200.0, 1.0, 0.5});   // a wide page: more columns than rows

    std::printf("%-52s %9s %12s %12s %12s %15s\n", "scale", "grid", "closed px", "predicted px", "dense px",
                "rows-1 dense px");
    for (const Scale& s : scales) {
        SCOPED_TRACE(describe(s));
        const double pixels = s.pixelsPerUnit * s.magnification;
        const GridResolution g = chooseGridResolution(s.width, s.height, CurlSchedule{}, s.pixelsPerUnit,
                                                      s.magnification, s.maxErrorPixels);
        const MeshDeviation dense = measureInParallel(gridFor(s.width, s.height, g.rows), s.height, denseTimes());
        const double densePx = dense.maxDistance * pixels;
        EXPECT_LE(densePx, s.maxErrorPixels) << g.rows << " rows: " << describe(dense);
        // The prediction is the coarse measurement, which can only be below the dense one, and
        // should be close: the coarse times include the worst moment.
        EXPECT_LE(g.predictedErrorPixels, densePx * (1.0 + 1e-9));
        EXPECT_GE(g.predictedErrorPixels, densePx * 0.99);

        double fewerPx = kNaN;
        if (g.rows > 8) {
            // Any part of the dense sweep that exceeds the bound is enough; the turn's tightest stretch
            // (t in [0.1, 0.2], 21 of the dense times) is tried first, the whole sweep only if needed.
            const PageGrid fewerGrid = gridFor(s.width, s.height, g.rows - 1);
            std::vector<double> tightest;
            for (double t : denseTimes()) {
                if (t >= 0.1 && t <= 0.2) tightest.push_back(t);
            }
            MeshDeviation fewer = measureInParallel(fewerGrid, s.height, tightest);
            if (!(fewer.maxDistance * pixels > 0.85 * s.maxErrorPixels)) {
                fewer = measureInParallel(fewerGrid, s.height, denseTimes());
            }
            fewerPx = fewer.maxDistance * pixels;
            EXPECT_GT(fewerPx, 0.85 * s.maxErrorPixels) << g.rows - 1 << " rows: " << describe(fewer);
        }
        // The closed form at the default schedule's worst moment (t = 0.15: 8 deg, apex -2.5 x height).
        const double dx = s.width / g.columns;
        const double closedPx = kCot8Deg / (8.0 * 2.5 * s.height) * dx * dx * pixels;
        std::printf("%-52s %4d x %-4d %12.4f %12.4f %12.4f %15.4f\n", describe(s).c_str(), g.rows, g.columns,
                    closedPx, g.predictedErrorPixels, densePx, fewerPx);
    }
}

// The renderer chooses by the closed form alone (no measuring at run time): it must pick what the
// measured choice picks, give or take a row, and what it picks must meet the budget on a dense sweep.
TEST(MeshResolution, ClosedFormChoiceAtRunTimeMatchesTheMeasuredChoiceAndMeetsTheBudget) {
    std::vector<Scale> scales;
    for (double ppu : {300.0, 800.0, 1600.0, 3000.0}) {
        for (double mag : {1.0, 1.6}) scales.push_back({kW, kH, ppu, mag, 0.5});
    }
    scales.push_back({kW, kH, 1600.0, 1.0, 0.25});
    scales.push_back({1.5, 2.0, 1000.0, 1.3, 0.5});
    scales.push_back({1.1, 1.0, 1200.0, 1.0, 0.5});
    scales.push_back({0.6, 1.0, 2000.0, 1.2, 0.5});
    for (const Scale& s : scales) {
        SCOPED_TRACE(describe(s));
        const GridResolution closed = closedFormGridResolution(s.width, s.height, CurlSchedule{}, s.pixelsPerUnit,
                                                               s.magnification, s.maxErrorPixels);
        const GridResolution measured = chooseGridResolution(s.width, s.height, CurlSchedule{}, s.pixelsPerUnit,
                                                             s.magnification, s.maxErrorPixels);
        EXPECT_NEAR(closed.rows, measured.rows, 1);
        EXPECT_LE(closed.predictedErrorPixels, s.maxErrorPixels);
        const double pixels = s.pixelsPerUnit * s.magnification;
        const MeshDeviation dense = measureInParallel(gridFor(s.width, s.height, closed.rows), s.height, denseTimes());
        // The closed form agrees with the measurement to ~0.1%: at most 1% over the budget.
        EXPECT_LE(dense.maxDistance * pixels, s.maxErrorPixels * 1.01) << closed.rows << " rows: " << describe(dense);
    }
    EXPECT_TRUE(std::isnan(closedFormGridResolution(0.0, 1.0, CurlSchedule{}, 100.0, 1.0).predictedErrorPixels));
    EXPECT_EQ(closedFormGridResolution(0.8, 1.0, CurlSchedule{}, -1.0, 1.0).rows, 8);
}

TEST(MeshResolution, RowsNeverShrinkAsPixelsPerUnitOrMagnificationGrow) {
    int previous = 0;
    for (double ppu = 50.0; ppu <= 40000.0; ppu *= 1.25) {
        const GridResolution g = chooseGridResolution(kW, kH, CurlSchedule{}, ppu, 1.0);
        EXPECT_GE(g.rows, previous) << "ppu " << ppu;
        previous = g.rows;
    }
    EXPECT_GT(previous, 8);  // the sweep left the floor
    previous = 0;
    for (double mag = 1.0; mag <= 4.0; mag += 0.25) {
        const GridResolution g = chooseGridResolution(kW, kH, CurlSchedule{}, 1500.0, mag);
        EXPECT_GE(g.rows, previous) << "magnification " << mag;
        previous = g.rows;
    }
    // A looser budget never needs more rows than a tighter one.
    EXPECT_LE(chooseGridResolution(kW, kH, CurlSchedule{}, 2000.0, 1.0, 1.0).rows,
              chooseGridResolution(kW, kH, CurlSchedule{}, 2000.0, 1.0, 0.5).rows);
}

TEST(MeshResolution, ColumnsFollowThePageAspectWithAtLeastFour) {
    // Widths up to 1.1 x the height: wider pages wrap past beta = pi (see the next test).
    for (double height : {1.0, 2.5}) {
        for (double width : {0.2, 0.5, 0.8, 1.0, 1.1}) {
            for (double ppu : {100.0, 700.0, 2500.0}) {
                const GridResolution g = chooseGridResolution(width, height, CurlSchedule{}, ppu, 1.2);
                EXPECT_EQ(g.columns, std::max(4L, std::lround(g.rows * width / height)))
                    << "page " << width << " x " << height << ", ppu " << ppu << ": " << g.rows << " x "
                    << g.columns;
            }
        }
    }
    EXPECT_EQ(chooseGridResolution(0.1, kH, CurlSchedule{}, 200.0, 1.0).columns, 4);
}

// Nuon's schedule wraps a page much wider than tall past beta = pi around its cone for much of the turn;
// cone_deform clamps beta there, which creases the surface, and no grid follows a crease. The closed
// form cannot see that; the verification must, and the answer must admit the budget is not met.
TEST(MeshResolution, PageTooWideForTheScheduleHitsMaxRowsAndSaysTheBudgetIsNotMet) {
    const GridResolution g = chooseGridResolution(1.6, kH, CurlSchedule{}, 1000.0, 1.0);
    EXPECT_EQ(g.rows, 256);
    EXPECT_GT(g.predictedErrorPixels, 0.5);
    const MeshDeviation d = measureMeshDeviation(gridFor(1.6, kH, 256), CurlSchedule{}, kH, {0.3});
    EXPECT_GT(d.maxDistance * 1000.0, 0.5) << describe(d);
}

TEST(MeshResolution, ClampsToMinRowsAndMaxRows) {
    // 20 px per unit: the 8-row floor sags ~0.02 px. A million px per unit would need ~850 rows.
    const GridResolution low = chooseGridResolution(kW, kH, CurlSchedule{}, 20.0, 1.0);
    EXPECT_EQ(low.rows, 8);
    EXPECT_LT(low.predictedErrorPixels, 0.5);
    const GridResolution high = chooseGridResolution(kW, kH, CurlSchedule{}, 1.0e6, 1.0);
    EXPECT_EQ(high.rows, 256);
    EXPECT_EQ(high.columns, 205);
    EXPECT_GT(high.predictedErrorPixels, 0.5);  // says honestly that the budget is not met

    // Custom bounds.
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, 20.0, 1.0, 0.5, 12, 40).rows, 12);
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, 1.0e6, 1.0, 0.5, 12, 40).rows, 40);
    const GridResolution inside = chooseGridResolution(kW, kH, CurlSchedule{}, 2000.0, 1.0, 0.5, 12, 400);
    EXPECT_GT(inside.rows, 12);
    EXPECT_LT(inside.rows, 400);
}

TEST(MeshResolution, DegenerateInputsGiveAUsableGrid) {
    // Nothing to resolve: the floor.
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, 0.0, 1.0).rows, 8);
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, kNaN, 1.0).rows, 8);
    // A budget that cannot be met: the ceiling.
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, 1000.0, 1.0, 0.0).rows, 256);
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, 1000.0, 1.0, kNaN).rows, 256);
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, 1000.0, 1.0, kInf).rows, 8);
    // Magnification below 1 or NaN counts as 1.
    const int atOne = chooseGridResolution(kW, kH, CurlSchedule{}, 2000.0, 1.0).rows;
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, 2000.0, 0.5).rows, atOne);
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, 2000.0, kNaN).rows, atOne);
    // A page with no size.
    const GridResolution none = chooseGridResolution(0.0, kH, CurlSchedule{}, 2000.0, 1.0);
    EXPECT_EQ(none.rows, 8);
    EXPECT_EQ(none.columns, 4);
    // Bounds out of order.
    EXPECT_EQ(chooseGridResolution(kW, kH, CurlSchedule{}, 2000.0, 1.0, 0.5, 0, -5).rows, 1);
}

// The renderer calls this on every canvas resize: it must be repeatable. Its cost is reported here
// (not asserted: timings belong in the report, not in a pass/fail).
TEST(MeshResolution, IsDeterministicAndReportsItsCostForA2000PixelPage) {
    for (double mag : {1.0, 1.6}) {
        const GridResolution first = chooseGridResolution(kW, kH, CurlSchedule{}, 2000.0, mag);
        double best = kInf;
        for (int i = 0; i < 7; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const GridResolution again = chooseGridResolution(kW, kH, CurlSchedule{}, 2000.0, mag);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            best = std::min(best, ms);
            EXPECT_EQ(again.rows, first.rows);
            EXPECT_EQ(again.columns, first.columns);
            EXPECT_EQ(again.predictedErrorPixels, first.predictedErrorPixels);
        }
        char line[160];
        std::snprintf(line, sizeof line,
                      "chooseGridResolution(2000 px/unit, magnification %.1f): %d x %d, %.4f px, %.2f ms", mag,
                      first.rows, first.columns, first.predictedErrorPixels, best);
        std::cout << line << std::endl;
        RecordProperty(mag == 1.0 ? "ms_2000px_mag1" : "ms_2000px_mag1_6", std::to_string(best));
    }
}

}  // namespace
