#include "lowpoly/inner_shells.h"

#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include "marching/mesh_checks.h"

namespace sylva {

std::size_t remove_inner_shells(Mesh& mesh) {
    const std::vector<double> volumes = component_volumes(mesh);
    std::size_t removed = 0;
    for (double v : volumes) removed += v > 0.0 ? 0 : 1;
    if (removed == 0) return 0;

    // The same labelling as component_volumes: components numbered by first triangle.
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const auto& t : mesh.triangles) {
        parent[find(t[1])] = find(t[0]);
        parent[find(t[2])] = find(t[0]);
    }
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> component(mesh.positions.size(), kNone);
    std::uint32_t next = 0;
    for (const auto& t : mesh.triangles)
        if (component[find(t[0])] == kNone) component[find(t[0])] = next++;

    Mesh kept;
    std::vector<std::uint32_t> index(mesh.positions.size(), kNone);
    for (const auto& t : mesh.triangles) {
        if (!(volumes[component[find(t[0])]] > 0.0)) continue;
        std::array<std::uint32_t, 3> u{};
        for (int k = 0; k < 3; ++k) {
            if (index[t[k]] == kNone) {
                index[t[k]] = static_cast<std::uint32_t>(kept.positions.size());
                kept.positions.push_back(mesh.positions[t[k]]);
            }
            u[k] = index[t[k]];
        }
        kept.triangles.push_back(u);
    }
    mesh = std::move(kept);
    return removed;
}

}  // namespace sylva
