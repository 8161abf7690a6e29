#include "ui/studio_state.h"

#include "app/export.h"
#include "app/lowpoly_tree.h"
#include "app/template_file.h"
#include "app/template_library.h"
#include "marching/marching_cubes.h"
#include "turtle/grammar_error.h"

#include <algorithm>
#include <exception>

namespace sylva::studio {
namespace {

bool ready(const auto& future) {
    return future.valid() &&
           future.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

Edit current_edit(const StudioState& state) {
    return {state.tree_template.grammar, state.tree_template.params};
}

// The triangle budget the view shows the tree at: 0 for the full marching-cubes meshes.
int preview_budget(const StudioState& state) {
    return state.view.low_poly ? std::max(state.export_settings.budget, 0) : 0;
}

void apply_edit(StudioState& state, const Edit& edit) {
    state.tree_template.grammar = edit.grammar;
    state.tree_template.params = edit.params;
    state.committed = edit;
    start_generation(state);
}

}  // namespace

bool Edit::operator==(const Edit& other) const {
    if (grammar != other.grammar || params.seed != other.params.seed) return false;
    for (const ParamInfo& info : param_infos())
        if (*get_param(params, info.key) != *get_param(other.params, info.key)) return false;
    return true;
}

void load_template_into(StudioState& state, const TreeTemplate& tree_template) {
    state.tree_template = tree_template;
    state.undo.clear();
    state.redo.clear();
    state.committed = current_edit(state);
    state.frame_next_tree = true;
    start_generation(state);
}

void start_generation(StudioState& state) {
    if (state.job) {
        state.job->cancel->store(true);
        state.stale.push_back(std::move(*state.job));
        state.job.reset();
    }
    state.requested = current_edit(state);
    GenerationJob job;
    job.started = std::chrono::steady_clock::now();
    job.tree_template = state.tree_template;
    // The worker gets its own copies: editing while it runs is safe.
    state.requested_budget = preview_budget(state);
    const auto budget = static_cast<std::size_t>(state.requested_budget);
    job.result = std::async(std::launch::async, [tree_template = state.tree_template, budget,
                                                 cancel = job.cancel, progress = job.progress] {
        MeshOptions options;
        options.cancel = cancel.get();
        options.progress = [progress](float f) { progress->store(f); };
        Tree tree = generate_tree(tree_template, options);
        if (budget > 0) {  // the game mesh, as an export with this budget would write it
            TreeBudget total;
            total.total = budget;
            DecimateSettings settings;
            settings.cancel = cancel.get();  // a newer edit stops a long reduction too
            ReducedTree reduced = reduce_tree(tree, total, settings);
            tree.trunk = std::move(reduced.trunk);
            tree.crown = std::move(reduced.crown);
        }
        return tree;
    });
    state.job = std::move(job);
}

bool generation_running(const StudioState& state) { return state.job.has_value(); }

void cancel_generations(StudioState& state) {
    if (state.job) state.job->cancel->store(true);
    for (GenerationJob& job : state.stale) job.cancel->store(true);
}

float generation_progress(const StudioState& state) {
    return state.job ? state.job->progress->load() : 1.0f;
}

void poll_jobs(StudioState& state) {
    std::erase_if(state.stale, [](GenerationJob& job) {
        if (!ready(job.result)) return false;
        try {
            job.result.get();
        } catch (...) {  // cancelled or failed: nobody waits for it any more
        }
        return true;
    });
    if (state.job && ready(state.job->result)) {
        GenerationJob job = std::move(*state.job);
        state.job.reset();
        state.last_wall_ms = std::chrono::duration<double, std::milli>(
                                 std::chrono::steady_clock::now() - job.started)
                                 .count();
        try {
            state.tree = job.result.get();
            state.shown_template = std::move(job.tree_template);
            state.tree_changed = true;
            state.error.clear();
            state.error_line = state.error_column = 0;
        } catch (const GrammarError& e) {
            // The GUI's error boundary: bad input becomes a message; the last tree stays.
            state.error = e.what();
            state.error_line = e.line();
            state.error_column = e.column();
        } catch (const MeshingCancelled&) {
        } catch (const DecimationCancelled&) {
        } catch (const std::exception& e) {
            state.error = e.what();
            state.error_line = state.error_column = 0;
        }
    }
    if (ready(state.export_job)) {
        try {
            state.export_message = state.export_job.get();
        } catch (const std::exception& e) {
            state.export_message = std::string("export failed: ") + e.what();
        }
    }
}

bool edit_pending(const StudioState& state) {
    return !(current_edit(state) == state.requested) ||
           preview_budget(state) != state.requested_budget;
}

bool commit_edit(StudioState& state) {
    Edit now = current_edit(state);
    if (now == state.committed) return false;
    state.undo.push_back(std::move(state.committed));
    state.redo.clear();
    state.committed = std::move(now);
    return true;
}

void undo(StudioState& state) {
    commit_edit(state);
    if (state.undo.empty()) return;
    state.redo.push_back(current_edit(state));
    Edit previous = std::move(state.undo.back());
    state.undo.pop_back();
    apply_edit(state, previous);
}

void redo(StudioState& state) {
    if (state.redo.empty()) return;
    state.undo.push_back(current_edit(state));
    Edit next = std::move(state.redo.back());
    state.redo.pop_back();
    apply_edit(state, next);
}

void start_export(StudioState& state) {
    if (!state.tree) {
        state.export_message = "nothing to export yet";
        return;
    }
    if (state.export_job.valid()) return;  // one export at a time
    state.export_message = "exporting...";
    state.export_job = std::async(std::launch::async, [tree = *state.tree,
                                                       tmpl = state.shown_template,
                                                       settings = state.export_settings] {
        std::string message;
        std::vector<std::filesystem::path> files;
        if (settings.lod) {
            std::vector<ReducedTree> levels =
                make_lod_chain(tree, lod_budgets(settings.budget > 0 ? settings.budget : 800, 4));
            std::vector<std::vector<NamedMesh>> named;
            for (size_t i = 0; i < levels.size(); ++i) {
                named.push_back(tree_parts(levels[i].trunk, levels[i].crown, tree.leaves, tmpl.colors));
                for (NamedMesh& part : named.back()) part.name += "_LOD" + std::to_string(i);
            }
            files = write_lod_chain(settings.path, named);
            message = "LOD0-LOD3, ";
        } else if (settings.budget > 0) {
            TreeBudget budget;
            budget.total = static_cast<std::size_t>(settings.budget);
            ReducedTree reduced = reduce_tree(tree, budget);
            files = write_model(settings.path,
                                tree_parts(reduced.trunk, reduced.crown, tree.leaves, tmpl.colors));
            message = std::to_string(reduced.triangles) + " trunk + crown triangles, ";
        } else {
            files = write_model(settings.path,
                                tree_parts(tree.trunk, tree.crown, tree.leaves, tmpl.colors));
            message = std::to_string(tree.trunk.triangles.size() + tree.crown.triangles.size()) +
                      " trunk + crown triangles, ";
        }
        message += "wrote";
        for (const auto& file : files) message += " " + file.string();
        return message;
    });
}

void save_template_to_file(StudioState& state) {
    try {
        save_template_file(state.template_path, state.tree_template);
        state.file_message = "saved " + state.template_path;
    } catch (const std::exception& e) {
        state.file_message = e.what();
    }
}

void open_template_file(StudioState& state) {
    try {
        load_template_into(state, load_template(state.template_path));
        state.file_message = "opened " + state.template_path;
    } catch (const std::exception& e) {
        state.file_message = e.what();
    }
}

}  // namespace sylva::studio
