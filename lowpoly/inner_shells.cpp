#include "lowpoly/inner_shells.h"

#include <cstdint>
#include <vector>

#include "lowpoly/merge_meshes.h"
#include "marching/mesh_checks.h"

namespace sylva {

std::size_t remove_inner_shells(Mesh& mesh) {
    const std::vector<double> volumes = component_volumes(mesh);
    std::size_t removed = 0;
    for (double v : volumes) removed += v > 0.0 ? 0 : 1;
    if (removed == 0) return 0;

    // The same numbering as component_volumes: label 0 keeps a triangle, 1 drops it.
    std::size_t components = 0;
    std::vector<std::uint32_t> label = component_of_triangles(mesh, components);
    for (std::uint32_t& l : label) l = volumes[l] > 0.0 ? 0 : 1;
    mesh = std::move(split_by_label(mesh, label, 1).front());
    return removed;
}

}  // namespace sylva
