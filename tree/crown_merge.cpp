#include "tree/crown_merge.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tuple>
#include <vector>

#include "core/disjoint_sets.h"
#include "sdf/point_hash.h"

namespace sylva {
namespace {

// Calls f(i, j, gap) for every pair i < j of spheres closer than twice `grow` for which
// wanted(i, j) holds (asked first, so an unwanted pair costs no distance).
template <class F, class W>
void for_each_close_pair(std::span<const Ball> balls, float grow, F&& f, W&& wanted) {
    float largest = 0.0f;
    for (const Ball& b : balls) largest = std::max(largest, b.radius);
    // Two balls touch only when their centres are closer than twice the largest grown
    // radius: with cells that wide, touching balls are in neighbouring cells.
    PointHash grid(std::max(2.0f * (largest + grow), 1e-6f));
    for (std::uint32_t i = 0; i < balls.size(); ++i) grid.insert(balls[i].center, i);
    for (std::uint32_t i = 0; i < balls.size(); ++i)
        grid.for_each_near(balls[i].center, [&](std::uint32_t j) {
            if (j <= i || !wanted(i, j)) return;
            const float gap =
                glm::distance(balls[i].center, balls[j].center) - balls[i].radius - balls[j].radius;
            if (gap < 2.0f * grow) f(i, j, gap);
        });
}

template <class F>
void for_each_close_pair(std::span<const Ball> balls, float grow, F&& f) {
    for_each_close_pair(balls, grow, f, [](std::uint32_t, std::uint32_t) { return true; });
}

// Grown by this much every ball reaches every other (half the centres' diagonal): the
// farthest any merge needs to look.
float reach_all(std::span<const Ball> balls) {
    glm::vec3 lo(balls[0].center), hi(balls[0].center);
    for (const Ball& b : balls) {
        lo = glm::min(lo, b.center);
        hi = glm::max(hi, b.center);
    }
    return 0.5f * glm::distance(lo, hi) + 1e-3f;
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

std::vector<std::pair<std::uint32_t, std::uint32_t>> crown_bridges(std::span<const Ball> balls,
                                                                   std::size_t max_pieces) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> bridges;
    if (balls.empty()) return bridges;
    // Kruskal's algorithm over the pairs of spheres in order of (gap, i, j), up to the first
    // pair with a positive gap once at most `max_pieces` pieces remain (touching pairs are
    // all joined: they are one piece anyway); the joins with a positive gap are the bridges.
    // The pairs come in bands of gaps, [2 * done, 2 * grow), each sorted alone and the next
    // twice as wide, until the forest gets to max_pieces (or to one piece) or the band
    // reaches every pair: the few pairs below the critical gap are all that is sorted, not
    // every pair within a guessed growth. A pair whose spheres are joined already when its
    // band starts is left out; it would join nothing, so the joins are Kruskal's over all
    // pairs.
    struct Gap {
        float gap;
        std::uint32_t i, j;
    };
    const float reach = reach_all(balls);
    DisjointSets sets(balls.size());
    std::size_t pieces = balls.size();
    std::vector<Gap> gaps;
    std::vector<std::uint32_t> piece(balls.size());
    float done = 0.0f;
    for (float grow = reach / 64.0f;; grow *= 2.0f) {
        grow = std::min(grow, reach);
        const bool first = done == 0.0f;
        for (std::uint32_t i = 0; i < balls.size(); ++i) piece[i] = sets.find(i);
        gaps.clear();
        for_each_close_pair(
            balls, grow,
            [&](std::uint32_t i, std::uint32_t j, float gap) {
                if (first || !(gap < 2.0f * done)) gaps.push_back({gap, i, j});
            },
            [&](std::uint32_t i, std::uint32_t j) { return piece[i] != piece[j]; });
        std::sort(gaps.begin(), gaps.end(), [](const Gap& a, const Gap& b) {
            return std::tie(a.gap, a.i, a.j) < std::tie(b.gap, b.i, b.j);
        });
        for (const Gap& g : gaps) {
            if (pieces <= max_pieces && g.gap > 0.0f) return bridges;
            if (!sets.unite(g.i, g.j)) continue;
            --pieces;
            if (g.gap > 0.0f) bridges.emplace_back(g.i, g.j);
        }
        if (pieces <= std::max<std::size_t>(max_pieces, 1) || grow >= reach) return bridges;
        done = grow;
    }
}

}  // namespace sylva
