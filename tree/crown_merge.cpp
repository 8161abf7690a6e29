#include "tree/crown_merge.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numeric>
#include <tuple>
#include <vector>

#include "core/disjoint_sets.h"
#include "sdf/point_hash.h"

namespace sylva {
namespace {

// Calls f(i, j, gap) for every pair i < j of spheres closer than twice `grow`.
template <class F>
void for_each_close_pair(std::span<const Ball> balls, float grow, F&& f) {
    float largest = 0.0f;
    for (const Ball& b : balls) largest = std::max(largest, b.radius);
    // Two balls touch only when their centres are closer than twice the largest grown
    // radius: with cells that wide, touching balls are in neighbouring cells.
    PointHash grid(std::max(2.0f * (largest + grow), 1e-6f));
    for (std::uint32_t i = 0; i < balls.size(); ++i) grid.insert(balls[i].center, i);
    for (std::uint32_t i = 0; i < balls.size(); ++i)
        grid.for_each_near(balls[i].center, [&](std::uint32_t j) {
            if (j <= i) return;
            const float gap =
                glm::distance(balls[i].center, balls[j].center) - balls[i].radius - balls[j].radius;
            if (gap < 2.0f * grow) f(i, j, gap);
        });
}

}  // namespace

std::size_t count_crown_pieces(std::span<const Ball> balls, float grow) {
    DisjointSets sets(balls.size());
    std::size_t pieces = balls.size();
    for_each_close_pair(balls, grow, [&](std::uint32_t i, std::uint32_t j, float) {
        if (sets.unite(i, j)) --pieces;
    });
    return pieces;
}

float crown_merge_radius(std::span<const Ball> balls, std::size_t max_pieces) {
    if (count_crown_pieces(balls, 0.0f) <= std::max<std::size_t>(max_pieces, 1)) return 0.0f;
    glm::vec3 lo(balls[0].center), hi(balls[0].center);
    for (const Ball& b : balls) {
        lo = glm::min(lo, b.center);
        hi = glm::max(hi, b.center);
    }
    // Grown by half the diagonal, every ball reaches every other: one piece.
    float low = 0.0f, high = 0.5f * glm::distance(lo, hi) + 1e-3f;
    const float precision = 0.01f * high;
    while (high - low > precision) {
        const float mid = 0.5f * (low + high);
        if (count_crown_pieces(balls, mid) <= max_pieces)
            high = mid;
        else
            low = mid;
    }
    return high;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> crown_bridges(std::span<const Ball> balls,
                                                                   std::size_t max_pieces) {
    const float grow = crown_merge_radius(balls, max_pieces);
    if (grow <= 0.0f) return {};
    struct Gap {
        float gap;
        std::uint32_t i, j;
    };
    std::vector<Gap> gaps;
    for_each_close_pair(balls, grow, [&](std::uint32_t i, std::uint32_t j, float gap) {
        gaps.push_back({gap, i, j});
    });
    std::sort(gaps.begin(), gaps.end(), [](const Gap& a, const Gap& b) {
        return std::tie(a.gap, a.i, a.j) < std::tie(b.gap, b.i, b.j);
    });
    DisjointSets sets(balls.size());
    std::size_t pieces = balls.size();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> bridges;
    for (const Gap& g : gaps) {
        if (pieces <= max_pieces && g.gap > 0.0f) break;  // what touches is joined anyway
        if (!sets.unite(g.i, g.j)) continue;
        --pieces;
        if (g.gap > 0.0f) bridges.emplace_back(g.i, g.j);
    }
    return bridges;
}

}  // namespace sylva
