#include "quality/weld.h"

#include <algorithm>
#include <numeric>

namespace sylva {

Welding weld_by_position(const Mesh& mesh) {
    const std::size_t n = mesh.positions.size();
    // Sorting (rather than hashing the float bits) keeps 0 and -0 together for free.
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    const auto less = [&](std::uint32_t a, std::uint32_t b) {
        const glm::vec3& p = mesh.positions[a];
        const glm::vec3& q = mesh.positions[b];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        if (p.z != q.z) return p.z < q.z;
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);

    // Each vertex first points at the first vertex of its point, then those get numbers.
    std::vector<std::uint32_t> first(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool same = i > 0 && mesh.positions[order[i]] == mesh.positions[order[i - 1]];
        first[order[i]] = same ? first[order[i - 1]] : order[i];
    }
    Welding welding;
    welding.vertex.assign(n, 0);
    std::vector<std::uint32_t> number(n, UINT32_MAX);
    for (std::size_t v = 0; v < n; ++v) {
        std::uint32_t& id = number[first[v]];
        if (id == UINT32_MAX) id = static_cast<std::uint32_t>(welding.count++);
        welding.vertex[v] = id;
    }
    return welding;
}

}  // namespace sylva
