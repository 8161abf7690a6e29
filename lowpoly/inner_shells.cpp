#include "lowpoly/inner_shells.h"

#include <cstdint>
#include <utility>
#include <vector>

#include "lowpoly/merge_meshes.h"
#include "marching/mesh_checks.h"

namespace sylva {

std::optional<Mesh> without_inner_shells(const Mesh& mesh, std::size_t* removed) {
    const std::vector<double> volumes = component_volumes(mesh);
    std::size_t inner = 0;
    for (double v : volumes) inner += v > 0.0 ? 0 : 1;
    if (removed) *removed = inner;
    if (inner == 0) return std::nullopt;

    // The same numbering as component_volumes: label 0 keeps a triangle, 1 drops it.
    std::size_t components = 0;
    std::vector<std::uint32_t> label = component_of_triangles(mesh, components);
    for (std::uint32_t& l : label) l = volumes[l] > 0.0 ? 0 : 1;
    return std::move(split_by_label(mesh, label, 1).front());
}

std::size_t remove_inner_shells(Mesh& mesh) {
    std::size_t removed = 0;
    if (std::optional<Mesh> solid = without_inner_shells(mesh, &removed)) mesh = std::move(*solid);
    return removed;
}

}  // namespace sylva
