// The page mesh as plain data: a regular grid of flat page coordinates and its triangle indices.
// The renderer uploads it once; the cone deformation happens per vertex in the shader.
#pragma once

#include <cstdint>
#include <vector>

namespace conecurl {

struct PageGrid {
    int columns = 0;  // quads across (x)
    int rows = 0;     // quads up (y)
    std::vector<float> points;        // (x, y) per vertex, row-major from the bottom-left corner
    std::vector<std::uint32_t> indices;  // two counter-clockwise triangles per quad (front faces +z)

    int vertexCount() const { return (columns + 1) * (rows + 1); }
};

// A grid over [0, width] x [0, height] with `columns` x `rows` quads (each at least 1).
PageGrid makePageGrid(double width, double height, int columns, int rows);

}  // namespace conecurl
