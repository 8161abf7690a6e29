// Exports the forest preview's square (ui/state/forest_preview_plan.h: the same ground, K
// variants and seed) as `sylva forest` writes a forest: one scene .glb with its placement
// lists (forest/forest.h), each variant at the edited template's triangle budget instead of
// the preview's low one, so what is written is the game forest the preview stands for.
#pragma once

#include <filesystem>
#include <string>

#include "core/tree_template.h"
#include "ui/state/forest_preview_plan.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {

// "tree.glb" -> "tree_forest.glb": where the studio writes the forest beside the tree.
std::filesystem::path forest_export_path(const std::filesystem::path& tree_path);

// A template budget of 0 (every triangle) plants at the preview's budget instead: a forest
// of full-detail trees is not a game forest.
// Plants and writes the forest (all files or none); returns the message the Export section
// shows ("wrote forest.glb (+ placements .csv, .json): 23 trees, 4 variants"). Throws
// InputError, IoError as forest::plant_forest does. Runs on the caller's thread (the studio
// calls it on a worker).
std::string export_forest(const TreeTemplate& tree, const ForestPreviewOptions& options,
                          const std::filesystem::path& glb);

// export_forest() of the edited template at export_budget() and the View row's forest
// options, on a worker
// (state.export_job: one export at a time), to forest_export_path(export_settings.path).
void start_forest_export(StudioState& state);

}  // namespace sylva::studio
