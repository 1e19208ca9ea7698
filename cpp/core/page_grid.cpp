// Builds the page grid; kept beside the math so it is unit-tested natively.
#include "page_grid.hpp"

#include <algorithm>

namespace conecurl {

PageGrid makePageGrid(double width, double height, int columns, int rows) {
    PageGrid grid;
    grid.columns = std::max(columns, 1);
    grid.rows = std::max(rows, 1);
    const int stride = grid.columns + 1;
    grid.points.reserve(static_cast<size_t>(grid.vertexCount()) * 2);
    for (int j = 0; j <= grid.rows; ++j) {
        for (int i = 0; i <= grid.columns; ++i) {
            grid.points.push_back(static_cast<float>(width * i / grid.columns));
            grid.points.push_back(static_cast<float>(height * j / grid.rows));
        }
    }
    grid.indices.reserve(static_cast<size_t>(grid.columns) * grid.rows * 6);
    for (int j = 0; j < grid.rows; ++j) {
        for (int i = 0; i < grid.columns; ++i) {
            const std::uint32_t a = j * stride + i;  // bottom-left of the quad
            const std::uint32_t b = a + 1;
            const std::uint32_t c = a + stride;
            const std::uint32_t d = c + 1;
            grid.indices.insert(grid.indices.end(), {a, b, d, a, d, c});
        }
    }
    return grid;
}

}  // namespace conecurl
