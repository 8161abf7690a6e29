#include "lowpoly/inner_shells.h"

#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include "core/disjoint_sets.h"
#include "marching/mesh_checks.h"

namespace sylva {

std::size_t remove_inner_shells(Mesh& mesh) {
    const std::vector<double> volumes = component_volumes(mesh);
    std::size_t removed = 0;
    for (double v : volumes) removed += v > 0.0 ? 0 : 1;
    if (removed == 0) return 0;

    // The same labelling as component_volumes: components numbered by first triangle.
    DisjointSets sets(mesh.positions.size());
    for (const auto& t : mesh.triangles) {
        sets.unite(t[1], t[0]);
        sets.unite(t[2], t[0]);
    }
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> component(mesh.positions.size(), kNone);
    std::uint32_t next = 0;
    for (const auto& t : mesh.triangles)
        if (component[sets.find(t[0])] == kNone) component[sets.find(t[0])] = next++;

    Mesh kept;
    std::vector<std::uint32_t> index(mesh.positions.size(), kNone);
    for (const auto& t : mesh.triangles) {
        if (!(volumes[component[sets.find(t[0])]] > 0.0)) continue;
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
