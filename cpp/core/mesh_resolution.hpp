// How fine the page grid must be: the GPU draws flat triangles between exactly curled vertices, so the
// mesh sags inside the cone's curve. This measures that sag against the C++ reference and picks the grid.
#pragma once

#include <vector>

#include "curl_schedule.hpp"
#include "page_grid.hpp"

namespace conecurl {

// Where the mesh strays farthest from the surface: the distance in world units, the turn time and
// the flat page point (x, y) at which it happens.
struct MeshDeviation {
    double maxDistance;
    double t;
    double x;
    double y;
};

// Largest distance, over the given turn times, between the piecewise-linear mesh of `grid` curled
// by curlAt(t, schedule, pageHeight) and the true curled surface, measured at each triangle's edge
// midpoints and centroid (plus a few interior barycentric samples), in world units.
// The mesh point and the surface point share a page coordinate: the barycentric combination of the
// triangle's flat corners is deformed exactly (cone_deform) and compared with the same combination of
// its deformed corners, as the GPU interpolates them. Distances are taken before the spine rotation,
// a rigid motion that moves mesh and surface alike (a test holds this against curlPoint), and an edge
// shared by two triangles is measured once. No times (or an empty grid) gives all zeros; a NaN
// distance is reported as NaN at once.
MeshDeviation measureMeshDeviation(const PageGrid& grid, const CurlSchedule& schedule, double pageHeight,
                                   const std::vector<double>& times);

struct GridResolution {
    int rows;
    int columns;
    double predictedErrorPixels;  // the mesh deviation the choice rests on, in screen pixels (see below)
};

// Smallest number of grid rows (columns follow the page's aspect: columns = max(4, round(rows * width /
// height))) such that the mesh deviation over the schedule, converted to pixels with `pixelsPerUnit`
// (screen pixels per world unit at the page plane) times `magnification` (how much nearer than the page
// plane a lifted leaf can come; the renderer passes its camera's worst case, >= 1), stays at or below
// `maxErrorPixels` (0.5 by default). Clamped to [minRows, maxRows] (defaults 8 and 256).
//
// How: across its rulings the cone bends with curvature k = cot(theta) / R at distance R from the
// apex, and a flat triangle sags below it by k w^2 / 8, w the triangle's extent across the rulings
// (at an edge midpoint). Both triangles of a cell of dx by dy have w = max(dx (y - Ay), dy x) / R,
// largest at the bottom of the spine (R = |apexY|), so the closed form is
//     max over t of cot(theta) / (8 |apexY|) * (width / columns)^2
// (and a like term in dy^2 that only matters for very flat cells). For Nuon's schedule the worst t is
// 0.15 (8 deg, apex -2.5 x height); the closed form agrees with the measurement to ~0.1%.
// The smallest row count the closed form accepts is the candidate; measureMeshDeviation then verifies
// it at a coarse set of times (the closed form's worst moments, the phase boundaries and t = 0.1, 0.3,
// 0.5, 0.7, 0.9), worst first so that a failing grid costs one time. A failure jumps up by the
// second-order law (sag ~ 1 / rows^2); a pass is confirmed smallest by measuring rows - 1 (and a
// bisection when that passes too). predictedErrorPixels is the verified coarse measurement in pixels.
// If even maxRows fails it is returned with the error measured at its worst time, above the budget:
// that happens with absurd scales (the default schedule needs ~256 rows near 90,000 px per unit) and
// with pages too wide for the schedule (wider than ~1.17 x their height, Nuon's schedule wraps the
// corner past beta = pi, which cone_deform clamps into a crease no grid can follow).
//
// Deterministic; one core, 2000 px per unit on Nuon's 0.8 x 1 page: ~15 ms (39 x 31; 8 time sweeps
// of ~15,000 curls). Degenerate input: magnification below 1 or NaN counts as 1; pixelsPerUnit <= 0
// or NaN means nothing to resolve (minRows); maxErrorPixels <= 0 or NaN cannot be met (maxRows);
// minRows < 1 counts as 1, maxRows below minRows as minRows; a page size that is not positive and
// finite gives minRows x 4 with NaN error.
GridResolution chooseGridResolution(double pageWidth, double pageHeight, const CurlSchedule& schedule,
                                    double pixelsPerUnit, double magnification, double maxErrorPixels = 0.5,
                                    int minRows = 8, int maxRows = 256);

// The closed form's choice alone, what the renderer uses at run time (well under a millisecond, where
// the verified choice above costs ~15 ms on every size change and zoom step): the smallest row count
// whose predicted sag is within budget, and that prediction in pixels. Native tests hold it to the
// measured choice over a sweep of page shapes and scales. Same degenerate cases as above.
GridResolution closedFormGridResolution(double pageWidth, double pageHeight, const CurlSchedule& schedule,
                                        double pixelsPerUnit, double magnification, double maxErrorPixels = 0.5,
                                        int minRows = 8, int maxRows = 256);

}  // namespace conecurl
