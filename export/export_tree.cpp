#include "export/export_tree.h"

namespace sylva {

std::vector<NamedMesh> tree_parts(const Mesh& trunk, const Mesh& crown, const Mesh& leaves,
                                  const PartColors& colors) {
    std::vector<NamedMesh> parts;
    if (!trunk.triangles.empty()) parts.push_back({"trunk", &trunk, colors.trunk, true});
    if (!crown.triangles.empty()) parts.push_back({"crown", &crown, colors.crown, true});
    if (!leaves.triangles.empty()) parts.push_back({"leaves", &leaves, colors.leaves, false});
    return parts;
}

SolidParts finest_solids(const Tree& tree, const FinishedTree& finished) {
    if (finished.levels.empty()) return {tree.trunk, tree.crown};
    return {finished.levels[0].trunk, finished.levels[0].crown};
}

std::size_t game_budget(const FinishSettings& settings) {
    const TreeBudget& b = settings.budget;
    if (settings.lod) return b.total > 0 ? b.total : kDefaultTriangleBudget;
    if (b.trunk && b.crown) return *b.trunk + *b.crown;
    return b.total;
}

FinishedTree finish_tree(const Tree& tree, const FinishSettings& settings) {
    FinishedTree out;
    const TreeBudget& budget = settings.budget;
    if (settings.lod) {
        const std::size_t finest = budget.total > 0 ? budget.total : kDefaultTriangleBudget;
        out.lod = true;
        out.budgets = lod_budgets(finest, settings.lod_levels);
        out.levels = make_lod_chain(tree, out.budgets, settings.decimate);
    } else if (budget.total > 0 || budget.trunk || budget.crown) {
        out.budgets = {budget.total};
        out.levels.push_back(reduce_tree(tree, budget, settings.decimate));
    }
    return out;
}

std::vector<ModelParts> finished_parts(const Tree& tree, const FinishedTree& finished,
                                       const PartColors& colors) {
    if (finished.levels.empty()) return {tree_parts(tree.trunk, tree.crown, tree.leaves, colors)};
    std::vector<ModelParts> levels;
    for (std::size_t i = 0; i < finished.levels.size(); ++i) {
        const ReducedTree& level = finished.levels[i];
        levels.push_back(tree_parts(level.trunk, level.crown, tree.leaves, colors));
        if (finished.lod)
            for (NamedMesh& part : levels.back()) part.name += "_LOD" + std::to_string(i);
    }
    return levels;
}

std::vector<std::filesystem::path> write_tree(const std::filesystem::path& path, const Tree& tree,
                                              const FinishedTree& finished,
                                              const PartColors& colors,
                                              const ExportOptions& options,
                                              const ExportFormat* format) {
    return write_lod_chain(path, finished_parts(tree, finished, colors), options, format);
}

}  // namespace sylva
