#include "tree/hull_gap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

namespace sylva {
namespace {

// The area of the convex hull of `p` (Andrew's monotone chain; sorts `p`).
double hull_area(std::vector<glm::vec2>& p) {
    if (p.size() < 3) return 0.0;
    std::sort(p.begin(), p.end(), [](const glm::vec2& a, const glm::vec2& b) {
        return a.x != b.x ? a.x < b.x : a.y < b.y;
    });
    auto turn = [](const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) {
        return static_cast<double>(a.x - o.x) * (b.y - o.y) -
               static_cast<double>(a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::vec2> hull(2 * p.size());
    std::size_t n = 0;
    for (const glm::vec2& q : p) {  // the lower chain
        while (n >= 2 && turn(hull[n - 2], hull[n - 1], q) <= 0.0) --n;
        hull[n++] = q;
    }
    const std::size_t lower = n + 1;
    for (std::size_t i = p.size() - 1; i-- > 0;) {  // the upper chain
        while (n >= lower && turn(hull[n - 2], hull[n - 1], p[i]) <= 0.0) --n;
        hull[n++] = p[i];
    }
    double twice = 0.0;
    for (std::size_t i = 0; i + 1 < n; ++i)
        twice += static_cast<double>(hull[i].x) * hull[i + 1].y -
                 static_cast<double>(hull[i + 1].x) * hull[i].y;
    return 0.5 * std::abs(twice);
}

// How many cells of side `cell` the points fall in.
std::size_t cells_covered(const std::vector<glm::vec2>& p, float cell) {
    std::vector<std::uint64_t> keys(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto x = static_cast<std::int64_t>(std::floor(p[i].x / cell)) + (1ll << 30);
        const auto y = static_cast<std::int64_t>(std::floor(p[i].y / cell)) + (1ll << 30);
        keys[i] = (static_cast<std::uint64_t>(x) << 32) | static_cast<std::uint64_t>(y);
    }
    std::sort(keys.begin(), keys.end());
    return static_cast<std::size_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
}

}  // namespace

double hull_gap(std::span<const glm::vec3> points, float cell) {
    if (points.size() < 3 || !(cell > 0.0f)) return 0.0;
    constexpr float kHalfRoot2 = 0.70710678f;
    // The side views' horizontal axes (x and z of it); the fifth view looks down.
    const std::array<glm::vec2, 4> sides{glm::vec2(1.0f, 0.0f), glm::vec2(kHalfRoot2, kHalfRoot2),
                                         glm::vec2(0.0f, 1.0f), glm::vec2(-kHalfRoot2, kHalfRoot2)};
    std::vector<glm::vec2> flat(points.size());
    double gap = 0.0;
    for (std::size_t view = 0; view <= sides.size(); ++view) {
        for (std::size_t i = 0; i < points.size(); ++i) {
            const glm::vec3& p = points[i];
            flat[i] = view < sides.size()
                          ? glm::vec2(sides[view].x * p.x + sides[view].y * p.z, p.y)
                          : glm::vec2(p.x, p.z);
        }
        const double covered =
            static_cast<double>(cells_covered(flat, cell)) * static_cast<double>(cell) * cell;
        gap += std::max(0.0, hull_area(flat) - covered);
    }
    return gap;
}

}  // namespace sylva
