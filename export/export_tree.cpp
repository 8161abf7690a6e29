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
        TreeBudget first = budget;
        first.total = finest;
        const std::vector<TreeBudget> budgets = lod_budgets(first, settings.lod_levels);
        for (const TreeBudget& b : budgets) {
            out.budgets.push_back(b.total);
            out.leaf_budgets.push_back(leaf_budget(b));
        }
        out.levels = make_lod_chain(tree, budgets, settings.decimate);
    } else if (budget.total > 0 || budget.trunk || budget.crown || budget.leaves) {
        out.budgets = {budget.total};
        out.leaf_budgets = {leaf_budget(budget)};
        out.levels.push_back(reduce_tree(tree, budget, settings.decimate));
    }
    return out;
}

std::vector<ModelParts> finished_parts(const Tree& tree, const FinishedTree& finished,
                                       const PartColors& colors) {
    if (finished.levels.empty()) return {tree_parts(tree.trunk, tree.crown, tree.leaves, colors)};
    std::vector<ModelParts> levels;
    for (const ReducedTree& level : finished.levels)
        levels.push_back(tree_parts(level.trunk, level.crown, level.leaves, colors));
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
