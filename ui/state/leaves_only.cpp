#include "ui/state/leaves_only.h"

#include <chrono>
#include <string_view>

#include "tree/parameters.h"

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
    // generate_tree's leaves: the crown's field as it meshes it (the resolution for the
    // template's budget decides which spheres merge).
    TreeParams p = edit.params;
    if (p.age < 1.0) return std::nullopt;
    const auto start = std::chrono::steady_clock::now();
    p.crown_resolution = crown_resolution_for_budget(
        p.crown_resolution, static_cast<std::size_t>(std::max(p.triangle_budget, 0)));
    // The crown's field only: the trunk's is not needed for leaves.
    const TreeFields fields = tree_fields(tree.skeleton, p, {}, cancel, TrunkField::None);
    Tree out = tree;
    out.leaves = tree_leaves(tree.skeleton, fields, p, cancel);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (StageTime& stage : out.times)
        if (stage.name == "leaves") stage.ms = ms;
    return out;
}

}  // namespace sylva::studio
