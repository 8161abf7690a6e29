#include "ui/state/forest_export.h"

#include <future>

#include "forest/forest.h"

namespace sylva::studio {

std::filesystem::path forest_export_path(const std::filesystem::path& tree_path) {
    std::filesystem::path out = tree_path;
    out.replace_filename(tree_path.stem().string() + "_forest.glb");
    return out;
}

std::string export_forest(const TreeTemplate& tree, const ForestPreviewOptions& options,
                          const std::filesystem::path& glb) {
    forest::ForestSettings settings = forest_preview_settings(tree, options);
    if (tree.params.triangle_budget > 0)
        settings.finish.budget.total = static_cast<std::size_t>(tree.params.triangle_budget);
    const forest::ForestResult result = forest::plant_forest(settings, glb);
    return "wrote " + glb.string() +
           " (+ placements .csv, .json): " + std::to_string(result.plan.placements.size()) +
           " trees, " + std::to_string(result.plan.variants.size()) + " variants";
}

void start_forest_export(StudioState& state) {
    if (state.export_job.valid()) return;  // one export at a time
    state.export_message = "planting the forest...";
    state.export_failed = false;
    TreeTemplate tree = state.tree_template;
    tree.params.triangle_budget = static_cast<int>(export_budget(state));
    state.export_job =
        std::async(std::launch::async, export_forest, std::move(tree), state.view.forest_options,
                   forest_export_path(state.export_settings.path));
}

}  // namespace sylva::studio
