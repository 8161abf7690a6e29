#include "tree/crown_merge.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace sylva {
namespace {

// A hash grid of cell `cell`: each ball in the cell of its centre.
struct BallGrid {
    float cell;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;

    static std::uint64_t key(glm::ivec3 c) {
        auto part = [](int v) {
            return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v) & 0x1fffff);
        };
        return part(c.x) | part(c.y) << 21 | part(c.z) << 42;
    }
    glm::ivec3 cell_of(const glm::vec3& p) const { return glm::ivec3(glm::floor(p / cell)); }
};

}  // namespace

std::size_t count_crown_pieces(std::span<const Ball> balls, float grow) {
    if (balls.empty()) return 0;
    float largest = 0.0f;
    for (const Ball& b : balls) largest = std::max(largest, b.radius);
    // Two balls touch only when their centres are closer than twice the largest grown
    // radius: with cells that wide, touching balls are in neighbouring cells.
    BallGrid grid{std::max(2.0f * (largest + grow), 1e-6f), {}};
    for (std::uint32_t i = 0; i < balls.size(); ++i)
        grid.cells[BallGrid::key(grid.cell_of(balls[i].center))].push_back(i);

    std::vector<std::uint32_t> parent(balls.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    std::size_t pieces = balls.size();
    for (std::uint32_t i = 0; i < balls.size(); ++i) {
        const glm::ivec3 c = grid.cell_of(balls[i].center);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto found = grid.cells.find(BallGrid::key(c + glm::ivec3(dx, dy, dz)));
                    if (found == grid.cells.end()) continue;
                    for (std::uint32_t j : found->second) {
                        if (j <= i) continue;
                        const float reach = balls[i].radius + balls[j].radius + 2.0f * grow;
                        if (glm::distance(balls[i].center, balls[j].center) >= reach) continue;
                        const std::uint32_t a = find(i), b = find(j);
                        if (a == b) continue;
                        parent[a] = b;
                        --pieces;
                    }
                }
    }
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

}  // namespace sylva
