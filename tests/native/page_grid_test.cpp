// Native (GoogleTest via CTest) tests of the page mesh: the renderer uploads makePageGrid() as is, so
// its counts, extent, index range and triangle winding (front faces +z) must be right by construction.
#include "page_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace {

using conecurl::makePageGrid;
using conecurl::PageGrid;

constexpr double kW = 0.8;  // Nuon's page
constexpr double kH = 1.0;

// Sizes from the degenerate single quad up to a fine mesh; (40, 50) is the 41 x 51 vertex grid.
const std::pair<int, int> kSizes[] = {{1, 1}, {1, 7}, {7, 1}, {3, 5}, {40, 50}, {64, 80}, {200, 250}};

struct Vec2 {
    double x, y;
};

Vec2 vertex(const PageGrid& g, std::uint32_t i) {
    return {g.points[2 * static_cast<size_t>(i)], g.points[2 * static_cast<size_t>(i) + 1]};
}

// Twice the signed area of triangle (a, b, c) seen from +z: positive when counter-clockwise.
double twiceSignedArea(Vec2 a, Vec2 b, Vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

std::string sizeName(int c, int r) { return std::to_string(c) + " x " + std::to_string(r) + " quads"; }

TEST(PageGrid, VertexCountIsColumnsPlusOneTimesRowsPlusOne) {
    for (auto [c, r] : kSizes) {
        const PageGrid g = makePageGrid(kW, kH, c, r);
        SCOPED_TRACE(sizeName(c, r));
        EXPECT_EQ(g.columns, c);
        EXPECT_EQ(g.rows, r);
        EXPECT_EQ(g.vertexCount(), (c + 1) * (r + 1));
        EXPECT_EQ(g.points.size(), 2u * static_cast<size_t>((c + 1) * (r + 1)));  // (x, y) pairs
    }
}

TEST(PageGrid, PointsSpanExactlyTheWholePageWithCornersPresent) {
    for (double W : {kW, 1.0, 2.5}) {
        for (double H : {kH, 1.375, 2.0}) {
            for (auto [c, r] : kSizes) {
                const PageGrid g = makePageGrid(W, H, c, r);
                SCOPED_TRACE(sizeName(c, r) + " on " + std::to_string(W) + " x " + std::to_string(H));
                // Points are float (what the GPU receives): the extent is W and H as float, exactly.
                const double fw = static_cast<float>(W);
                const double fh = static_cast<float>(H);
                double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
                for (int i = 0; i < g.vertexCount(); ++i) {
                    const Vec2 p = vertex(g, i);
                    minX = std::min(minX, p.x);
                    maxX = std::max(maxX, p.x);
                    minY = std::min(minY, p.y);
                    maxY = std::max(maxY, p.y);
                }
                EXPECT_EQ(minX, 0.0);
                EXPECT_EQ(maxX, fw);
                EXPECT_EQ(minY, 0.0);
                EXPECT_EQ(maxY, fh);

                // Row-major from the bottom-left: the corners sit at the first and last index of the
                // bottom and top rows.
                const std::uint32_t stride = c + 1;
                const std::uint32_t corners[4] = {0, stride - 1, r * stride, (r + 1) * stride - 1};
                const Vec2 want[4] = {{0.0, 0.0}, {fw, 0.0}, {0.0, fh}, {fw, fh}};
                for (int k = 0; k < 4; ++k) {
                    EXPECT_EQ(vertex(g, corners[k]).x, want[k].x) << "corner " << k;
                    EXPECT_EQ(vertex(g, corners[k]).y, want[k].y) << "corner " << k;
                }

                // Every vertex is the regular lattice point (i W / c, j H / r), to float rounding
                // (half an ulp of a float <= 2.5 is 1.2e-7).
                double worst = 0.0;
                for (int j = 0; j <= r; ++j) {
                    for (int i = 0; i <= c; ++i) {
                        const Vec2 p = vertex(g, j * stride + i);
                        worst = std::max({worst, std::abs(p.x - W * i / c), std::abs(p.y - H * j / r)});
                    }
                }
                EXPECT_LE(worst, 2.4e-7);
            }
        }
    }
}

TEST(PageGrid, IndexCountIsSixPerQuadAndAllIndicesAreInRange) {
    for (auto [c, r] : kSizes) {
        const PageGrid g = makePageGrid(kW, kH, c, r);
        SCOPED_TRACE(sizeName(c, r));
        ASSERT_EQ(g.indices.size(), static_cast<size_t>(c) * r * 6);
        const std::uint32_t maxIndex = *std::max_element(g.indices.begin(), g.indices.end());
        EXPECT_LT(maxIndex, static_cast<std::uint32_t>(g.vertexCount()));
        // And every vertex is used by some triangle (no stray points in the upload).
        std::vector<bool> used(g.vertexCount(), false);
        for (std::uint32_t i : g.indices) used[i] = true;
        EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
    }
}

// Front faces are counter-clockwise seen from +z (the viewer's side of the resting page); a clockwise
// triangle would be culled or textured with the back. The triangles also tile the page exactly once.
TEST(PageGrid, EveryTriangleIsCounterClockwiseFromPlusZAndTheyTileThePage) {
    for (auto [c, r] : kSizes) {
        const PageGrid g = makePageGrid(kW, kH, c, r);
        SCOPED_TRACE(sizeName(c, r));
        double minArea2 = 1e300;
        size_t worstTri = 0;
        double totalArea = 0.0;
        for (size_t k = 0; k + 2 < g.indices.size(); k += 3) {
            const double a2 = twiceSignedArea(vertex(g, g.indices[k]), vertex(g, g.indices[k + 1]),
                                              vertex(g, g.indices[k + 2]));
            if (a2 < minArea2) {
                minArea2 = a2;
                worstTri = k / 3;
            }
            totalArea += 0.5 * a2;
        }
        // Each triangle is half a quad: area W H / (2 c r), so strictly positive, not just >= 0.
        EXPECT_GT(minArea2, 0.0) << "triangle " << worstTri << " is clockwise or degenerate";
        // Float vertices are off by <= 6e-8 (half an ulp at 1) and quad sides are >= 0.0032 long, so
        // each side is off by <= 4e-5 relative: 1e-4 relative on the area.
        EXPECT_NEAR(minArea2, kW * kH / (c * r), 1e-4 * kW * kH / (c * r));
        // Sum of the positive areas equals the page: no overlap, no hole (float vertices: 1e-6).
        EXPECT_NEAR(totalArea, kW * kH, 1e-6);
    }
}

TEST(PageGrid, ColumnsAndRowsBelowOneAreClampedToOne) {
    const std::pair<int, int> cases[] = {{0, 0}, {-5, -3}, {0, 10}, {10, 0}, {-2147483647, 1}};
    for (auto [c, r] : cases) {
        const PageGrid g = makePageGrid(kW, kH, c, r);
        SCOPED_TRACE(sizeName(c, r));
        const int wantC = std::max(c, 1);
        const int wantR = std::max(r, 1);
        EXPECT_EQ(g.columns, wantC);
        EXPECT_EQ(g.rows, wantR);
        EXPECT_EQ(g.vertexCount(), (wantC + 1) * (wantR + 1));
        EXPECT_EQ(g.points.size(), 2u * static_cast<size_t>(g.vertexCount()));
        EXPECT_EQ(g.indices.size(), static_cast<size_t>(wantC) * wantR * 6);
        // Still the whole page.
        EXPECT_EQ(g.points[2 * (g.vertexCount() - 1)], static_cast<float>(kW));
        EXPECT_EQ(g.points[2 * (g.vertexCount() - 1) + 1], static_cast<float>(kH));
    }
}

}  // namespace
