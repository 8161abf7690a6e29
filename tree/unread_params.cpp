#include "tree/unread_params.h"

#include <string_view>

#include "tree/growth.h"
#include "tree/parameters.h"

namespace sylva {

std::map<std::string, std::string, std::less<>> unread_params(const TreeTemplate& tree) {
    std::map<std::string, std::string, std::less<>> unread;
    // The first reason for a key stands.
    auto mark = [&](std::string_view key, std::string reason) {
        unread.emplace(std::string(key), std::move(reason));
    };
    const GrowthMethod* method = find_growth_method(tree.growth);
    if (method && method->unread)
        for (UnreadParam& u : method->unread(tree, with_template_crowns({})))
            mark(u.key, std::move(u.reason));
    for (const ParamInfo& info : param_infos())
        if (!info.owner.empty() && info.owner != tree.growth)
            mark(info.key, "a parameter of growth method " + std::string(info.owner) +
                               ": this tree grows by " + tree.growth + " (switch growth to " +
                               std::string(info.owner) + ")");
    const TreeParams& p = tree.params;
    if (p.leaf_density <= 0.0)
        for (std::string_view key : {"leaf_size", "leaf_shape"})
            mark(key, "leaf_density is 0: the crown carries no leaves");
    if (!p.crown_mesh)
        for (std::string_view key : {"crown_resolution", "crown_blend", "crown_fusion",
                                     "crown_shape", "crown_lump_triangles"})
            mark(key, "crown_mesh is off: the crown is not meshed (its leaves stay)");
    if (p.triangle_budget == 0) {
        mark("crown_shape", "triangle_budget is 0: the game mesh keeps the crown as meshed");
        mark("branch_style", "triangle_budget is 0: the game mesh keeps the trunk as meshed");
    }
    if (p.triangle_budget == 0 || crown_shape_info(p.crown_shape).hulls == CrownHulls::Never)
        mark("crown_lump_triangles", "the game mesh draws the crown as blobs, not as lumps");
    if (p.sphere_diameter <= 0.0)
        for (std::string_view key :
             {"crown_resolution", "crown_blend", "crown_fusion", "crown_offset", "leaf_density",
              "leaf_size", "leaf_shape", "crown_mesh", "crown_merge", "crown_shape",
              "crown_lump_triangles"})
            mark(key, "sphere_diameter is 0: the tree has no crown");
    return unread;
}

}  // namespace sylva
