#include "lowpoly/inner_shells.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/mesh_checks.h"
#include "lowpoly/merge_meshes.h"

namespace sylva {

std::optional<Mesh> without_inner_shells(const Mesh& mesh) {
    const std::vector<double> volumes = component_volumes(mesh);
    if (std::all_of(volumes.begin(), volumes.end(), [](double v) { return v > 0.0; }))
        return std::nullopt;

    // The same numbering as component_volumes: label 0 keeps a triangle, 1 drops it.
    std::size_t components = 0;
    std::vector<std::uint32_t> label = component_of_triangles(mesh, components);
    for (std::uint32_t& l : label) l = volumes[l] > 0.0 ? 0 : 1;
    return std::move(split_by_label(mesh, label, 1).front());
}

}  // namespace sylva
