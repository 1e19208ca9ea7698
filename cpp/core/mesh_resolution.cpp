// Mesh sag against the exact cone, and the grid size that keeps it under half a pixel; the closed form
// behind the choice is derived in mesh_resolution.hpp and checked against the measurement in the tests.
#include "mesh_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "cone_deform.hpp"

namespace conecurl {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Barycentric sample points: each edge's midpoint (where a flat triangle sags most under a surface
// curved in one direction), then the centroid and three interior points halfway between midpoints.
constexpr double kEdgeMidpoint[3] = {0.5, 0.5, 0.0};
constexpr double kInteriorSamples[][3] = {
    {1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.5, 0.25, 0.25}, {0.25, 0.5, 0.25}, {0.25, 0.25, 0.5},
};

// measureMeshDeviation over `times` in the given order, returning as soon as a whole time has been
// measured and the maximum so far exceeds `stopAbove` (the result is then a lower bound).
// An edge midpoint is the same point for both triangles that share the edge, so on a grid whose
// edges join vertices 1, stride or stride + 1 apart (every makePageGrid) it is measured once per time.
MeshDeviation deviationOverTimes(const PageGrid& grid, const CurlSchedule& schedule, double pageHeight,
                                 const std::vector<double>& times, double stopAbove) {
    MeshDeviation worst{0.0, 0.0, 0.0, 0.0};
    const std::size_t vertexCount = grid.points.size() / 2;
    if (vertexCount == 0) return worst;

    std::vector<glm::dvec2> flat(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i) flat[i] = {grid.points[2 * i], grid.points[2 * i + 1]};
    std::vector<glm::dvec3> curled(vertexCount);
    const std::size_t stride = static_cast<std::size_t>(std::max(grid.columns, 1)) + 1;
    std::vector<char> edgeDone(3 * vertexCount);

    bool first = true;
    for (double t : times) {
        const CurlParams params = sanitize(curlAt(t, schedule, pageHeight));
        for (std::size_t i = 0; i < vertexCount; ++i) curled[i] = deformOntoCone(flat[i], params);
        std::fill(edgeDone.begin(), edgeDone.end(), 0);

        // Returns false on NaN, which is reported at once.
        const auto sample = [&](const double* w, std::uint32_t i0, std::uint32_t i1, std::uint32_t i2) {
            const glm::dvec2 q = w[0] * flat[i0] + w[1] * flat[i1] + w[2] * flat[i2];
            const glm::dvec3 onMesh = w[0] * curled[i0] + w[1] * curled[i1] + w[2] * curled[i2];
            const double d = glm::distance(onMesh, deformOntoCone(q, params));
            if (first || d > worst.maxDistance || std::isnan(d)) {
                worst = {d, t, q.x, q.y};
                first = false;
            }
            return !std::isnan(d);
        };
        // True the first time the edge (u, v) is met in this time's pass (always for an unkeyed edge).
        const auto firstVisit = [&](std::uint32_t u, std::uint32_t v) {
            const std::size_t lo = std::min(u, v);
            const std::size_t gap = std::max(u, v) - lo;
            const int kind = gap == 1 ? 0 : gap == stride ? 1 : gap == stride + 1 ? 2 : -1;
            if (kind < 0) return true;
            char& done = edgeDone[3 * lo + static_cast<std::size_t>(kind)];
            if (done) return false;
            done = 1;
            return true;
        };

        for (std::size_t k = 0; k + 2 < grid.indices.size(); k += 3) {
            const std::uint32_t v[3] = {grid.indices[k], grid.indices[k + 1], grid.indices[k + 2]};
            if (v[0] >= vertexCount || v[1] >= vertexCount || v[2] >= vertexCount) continue;
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t a = v[e], b = v[(e + 1) % 3];
                if (firstVisit(a, b) && !sample(kEdgeMidpoint, a, b, a)) return worst;
            }
            for (const auto& w : kInteriorSamples) {
                if (!sample(w, v[0], v[1], v[2])) return worst;
            }
        }
        if (worst.maxDistance > stopAbove) break;
    }
    return worst;
}

int columnsFor(int rows, double aspect) {
    const double c = std::round(rows * aspect);
    return c >= 4.0 ? static_cast<int>(std::min(c, 1.0e9)) : 4;
}

// The closed form, per turn time: the curvature across the rulings is cot(theta) / R; a triangle
// sags by (k / 8) w^2 with w its extent across the rulings. On a grid cell at page point (x, y) that
// extent is max(dx * (y - Ay), dy * x) / R (both triangles of the quad), so the sag is at most
// cot(theta) / 8 * max(dx^2 (y - Ay)^2, dy^2 x^2) / R^3. Over the page (R >= |Ay|) the first term peaks
// at the bottom of the spine, cot(theta) / |Ay| * dx^2, and the second at y = 0, x = min(W, sqrt(2)|Ay|).
struct SagCoefficients {
    double across = 0.0;  // multiplies dx^2 / 8
    double along = 0.0;   // multiplies dy^2 / 8
};

SagCoefficients sagCoefficients(double t, const CurlSchedule& schedule, double pageWidth, double pageHeight) {
    const CurlParams p = sanitize(curlAt(t, schedule, pageHeight));
    const double cotTheta = std::cos(p.theta) / std::sin(p.theta);
    const double a = -p.apexY;
    const double x = std::min(pageWidth, std::sqrt(2.0) * a);
    const double r2 = x * x + a * a;
    return {cotTheta / a, cotTheta * x * x / (r2 * std::sqrt(r2))};
}

double closedFormSag(const SagCoefficients& c, double pageWidth, double pageHeight, int columns, int rows) {
    const double dx = pageWidth / columns;
    const double dy = pageHeight / rows;
    return std::max(c.across * dx * dx, c.along * dy * dy) / 8.0;
}

}  // namespace

MeshDeviation measureMeshDeviation(const PageGrid& grid, const CurlSchedule& schedule, double pageHeight,
                                   const std::vector<double>& times) {
    return deviationOverTimes(grid, schedule, pageHeight, times, kInf);
}

namespace {

// The closed form's choice: its worst coefficients over a dense sweep of the turn (cheap: one curlAt
// per time), when they happen, and the smallest row count whose predicted sag is within `budget`.
struct ClosedFormChoice {
    SagCoefficients worst;
    double worstAcrossT = 0.0;
    double worstAlongT = 0.0;
    int rows = 0;
};

ClosedFormChoice closedFormChoice(double pageWidth, double pageHeight, const CurlSchedule& schedule, double budget,
                                  int minRows, int maxRows) {
    constexpr int kSweep = 2000;
    ClosedFormChoice choice;
    std::vector<double> sweep;
    sweep.reserve(kSweep + 3);
    for (int i = 0; i <= kSweep; ++i) sweep.push_back(static_cast<double>(i) / kSweep);
    sweep.push_back(schedule.phase1End);
    sweep.push_back(schedule.phase2End);
    for (double t : sweep) {
        const SagCoefficients c = sagCoefficients(t, schedule, pageWidth, pageHeight);
        if (c.across > choice.worst.across) choice.worst.across = c.across, choice.worstAcrossT = t;
        if (c.along > choice.worst.along) choice.worst.along = c.along, choice.worstAlongT = t;
    }
    const double aspect = pageWidth / pageHeight;
    choice.rows = maxRows;
    for (int r = minRows; r <= maxRows; ++r) {
        if (closedFormSag(choice.worst, pageWidth, pageHeight, columnsFor(r, aspect), r) <= budget) {
            choice.rows = r;
            break;
        }
    }
    return choice;
}

}  // namespace

namespace {

// The inputs both choices share, checked once: degenerate ones answer at once (`early`).
struct GridBudget {
    bool early = false;
    GridResolution answer{};  // when early
    double aspect = 1.0;
    double pixelsPerWorld = 0.0;
    double budget = -1.0;     // world units; NaN or <= 0 pixels cannot be met: no row count passes below maxRows
    int minRows = 1;
    int maxRows = 1;
};

GridBudget gridBudget(double pageWidth, double pageHeight, double pixelsPerUnit, double magnification,
                      double maxErrorPixels, int minRows, int maxRows) {
    GridBudget b;
    b.minRows = std::max(minRows, 1);
    b.maxRows = std::max(maxRows, b.minRows);
    if (!(pageWidth > 0.0 && pageHeight > 0.0 && std::isfinite(pageWidth) && std::isfinite(pageHeight))) {
        b.early = true;
        b.answer = {b.minRows, 4, kNaN};
        return b;
    }
    b.aspect = pageWidth / pageHeight;
    b.pixelsPerWorld = pixelsPerUnit * (magnification >= 1.0 ? magnification : 1.0);
    if (!(b.pixelsPerWorld > 0.0)) {
        b.early = true;
        b.answer = {b.minRows, columnsFor(b.minRows, b.aspect), 0.0};
        return b;
    }
    b.budget = maxErrorPixels > 0.0 ? maxErrorPixels / b.pixelsPerWorld : -1.0;
    return b;
}

}  // namespace

GridResolution closedFormGridResolution(double pageWidth, double pageHeight, const CurlSchedule& schedule,
                                        double pixelsPerUnit, double magnification, double maxErrorPixels,
                                        int minRows, int maxRows) {
    const GridBudget b = gridBudget(pageWidth, pageHeight, pixelsPerUnit, magnification, maxErrorPixels, minRows, maxRows);
    if (b.early) return b.answer;
    const ClosedFormChoice choice = closedFormChoice(pageWidth, pageHeight, schedule, b.budget, b.minRows, b.maxRows);
    const int columns = columnsFor(choice.rows, b.aspect);
    return {choice.rows, columns, closedFormSag(choice.worst, pageWidth, pageHeight, columns, choice.rows) * b.pixelsPerWorld};
}

GridResolution chooseGridResolution(double pageWidth, double pageHeight, const CurlSchedule& schedule,
                                    double pixelsPerUnit, double magnification, double maxErrorPixels,
                                    int minRows, int maxRows) {
    const GridBudget b = gridBudget(pageWidth, pageHeight, pixelsPerUnit, magnification, maxErrorPixels, minRows, maxRows);
    if (b.early) return b.answer;
    const double aspect = b.aspect, pixelsPerWorld = b.pixelsPerWorld, budget = b.budget;
    minRows = b.minRows;
    maxRows = b.maxRows;

    // The closed form's candidate; its worst moments lead the verification times, so a failing
    // candidate is found out after measuring one time.
    const ClosedFormChoice choice = closedFormChoice(pageWidth, pageHeight, schedule, budget, minRows, maxRows);
    const double worstAcrossT = choice.worstAcrossT, worstAlongT = choice.worstAlongT;
    int rows = choice.rows;

    // Coarse verification times: the closed form's worst moments, the phase boundaries and every 0.2
    // of the turn from 0.1, ordered worst first by the closed form at the candidate's cell size.
    std::vector<double> times = {worstAcrossT, worstAlongT, schedule.phase1End, schedule.phase2End,
                                 0.1, 0.3, 0.5, 0.7, 0.9};
    for (double& t : times) t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
    {
        const int columns = columnsFor(rows, aspect);
        std::vector<std::pair<double, double>> keyed;
        for (double t : times) {
            keyed.push_back({-closedFormSag(sagCoefficients(t, schedule, pageWidth, pageHeight), pageWidth,
                                            pageHeight, columns, rows),
                             t});
        }
        std::sort(keyed.begin(), keyed.end());
        times.clear();
        for (const auto& [key, t] : keyed) {
            if (std::find(times.begin(), times.end(), t) == times.end()) times.push_back(t);
        }
    }

    // A failing grid is found out after its first (worst) time; a passing one is measured at all.
    const auto verify = [&](int r) {
        const PageGrid grid = makePageGrid(pageWidth, pageHeight, columnsFor(r, aspect), r);
        return deviationOverTimes(grid, schedule, pageHeight, times, budget).maxDistance;
    };
    const auto passes = [&](double deviation) { return deviation <= budget; };

    // Up from the candidate while it fails, jumping by the second-order law (sag ~ 1 / rows^2) so
    // that a page the closed form misjudges costs a few measurements, not one per row.
    int failing = minRows - 1;  // highest row count known to fail (minRows - 1: none known)
    double deviation = verify(rows);
    while (!passes(deviation)) {
        failing = rows;
        if (rows >= maxRows) return {rows, columnsFor(rows, aspect), deviation * pixelsPerWorld};
        const double law = std::ceil(rows * std::sqrt(deviation / budget));
        const int next = law < maxRows ? static_cast<int>(law) : maxRows;
        rows = std::clamp(next, rows + 1, maxRows);
        deviation = verify(rows);
    }
    // Down to the smallest passing count: usually one failing measurement of rows - 1 settles it;
    // otherwise bisect between the highest known failure and the lowest known pass.
    if (failing < rows - 1) {
        const double fewer = verify(rows - 1);
        if (passes(fewer)) {
            --rows;
            deviation = fewer;
        } else {
            failing = rows - 1;
        }
    }
    while (failing < rows - 1) {
        const int mid = failing + (rows - failing) / 2;
        const double d = verify(mid);
        if (passes(d)) {
            rows = mid;
            deviation = d;
        } else {
            failing = mid;
        }
    }
    return {rows, columnsFor(rows, aspect), deviation * pixelsPerWorld};
}

}  // namespace conecurl
