// An axis-aligned box in world space that grows to hold points, and the rectangle of a target's
// pixels it covers once projected: what rests is laid down over that rectangle only (book_renderer.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace conecurl {

struct WorldBox {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};

    bool empty() const { return lo.x > hi.x; }
    void add(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void add(const WorldBox& box) {
        if (!box.empty()) {
            add(box.lo);
            add(box.hi);
        }
    }
    // Every vertex of a mesh of `stride` floats a vertex, its position first.
    static WorldBox of(const std::vector<float>& mesh, int stride) {
        WorldBox box;
        for (size_t i = 0; i + 2 < mesh.size(); i += static_cast<size_t>(stride)) box.add({mesh[i], mesh[i + 1], mesh[i + 2]});
        return box;
    }
};

// x, y, width, height in pixels of a `width` x `height` target (y up, as GL's), holding the projection
// of `box` with `margin` pixels about it, clamped to the target; the whole target where a corner lies
// behind the eye; an empty rectangle for an empty box.
inline std::array<int, 4> pixelRect(const WorldBox& box, const glm::mat4& viewProjection, int width, int height, int margin) {
    if (box.empty()) return {0, 0, 0, 0};
    float x0 = std::numeric_limits<float>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y, (corner & 4) ? box.hi.z : box.lo.z);
        const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
        if (!(clip.w > 1e-6f)) return {0, 0, width, height};
        const float x = (clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(width);
        const float y = (clip.y / clip.w * 0.5f + 0.5f) * static_cast<float>(height);
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x);
        y1 = std::max(y1, y);
    }
    const int left = std::clamp(static_cast<int>(std::floor(x0)) - margin, 0, width);
    const int bottom = std::clamp(static_cast<int>(std::floor(y0)) - margin, 0, height);
    const int right = std::clamp(static_cast<int>(std::ceil(x1)) + margin, 0, width);
    const int top = std::clamp(static_cast<int>(std::ceil(y1)) + margin, 0, height);
    return {left, bottom, std::max(0, right - left), std::max(0, top - bottom)};
}

}  // namespace conecurl
