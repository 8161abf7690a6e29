#include "ui/leaves_only.h"

#include <chrono>
#include <cmath>
#include <string_view>

#include "tree/leaves.h"

namespace sylva::studio {
namespace {

bool leaf_key(std::string_view key) {
    return key == "leaf_density" || key == "leaf_size" || key == "leaf_shape";
}

}  // namespace

bool leaves_only_edit(const TreeTemplate& a, const TreeTemplate& b) {
    if (a.growth != b.growth || a.grammar != b.grammar || a.mode != b.mode ||
        a.width_model != b.width_model || a.params.seed != b.params.seed)
        return false;
    for (const ParamInfo& info : param_infos())
        if (!leaf_key(info.key) && *get_param(a.params, info.key) != *get_param(b.params, info.key))
            return false;
    return true;
}

std::optional<Tree> with_new_leaves(const Tree& tree, const TreeTemplate& edit, CancelFlag cancel) {
    // generate_tree's leaves, step by step: the crown's field as it meshes it (the resolution
    // for the template's budget decides which spheres merge), scattered over or, behind a
    // meshed crown, in a shell one leaf deep; then the turtle's polygons.
    TreeParams p = edit.params;
    if (p.age < 1.0) return std::nullopt;
    const auto start = std::chrono::steady_clock::now();
    p.crown_resolution = crown_resolution_for_budget(
        p.crown_resolution, static_cast<std::size_t>(std::max(p.triangle_budget, 0)));
    const TreeFields fields = tree_fields(tree.skeleton, p, {}, cancel);
    Tree out = tree;
    out.leaves = Mesh{};
    const bool mesh_crown = fields.crown && p.crown_mesh != 0;
    if (fields.crown && p.leaf_density > 0.0) {
        LeafSettings leaves;
        leaves.density = p.leaf_density;
        leaves.size = p.leaf_size;
        leaves.shape = static_cast<LeafShape>(p.leaf_shape);
        leaves.seed = p.seed;
        leaves.cancel = cancel;
        const SphereField& crown = *fields.crown;
        const float shell = static_cast<float>(p.leaf_size);
        if (mesh_crown && crown.is_distance_bound() && shell > 0.0f)
            out.leaves = scatter_leaves(
                [&crown, shell](const glm::vec3& q) {
                    return std::abs(crown(q) + 0.5f * shell) - 0.5f * shell;
                },
                fields.crown_box, leaves);
        else
            out.leaves = scatter_leaves([&crown](const glm::vec3& q) { return crown(q); },
                                        fields.crown_box, leaves);
    }
    add_polygon_leaves(out.leaves, out.skeleton.polygons);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (StageTime& stage : out.times)
        if (stage.name == "leaves") stage.ms = ms;
    return out;
}

}  // namespace sylva::studio
