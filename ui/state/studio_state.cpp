#include "ui/state/studio_state.h"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "core/atomic_file.h"
#include "core/color_variation.h"
#include "core/errors.h"
#include "core/input_file.h"
#include "core/output_folder.h"
#include "export/export_tree.h"
#include "marching/marching_cubes.h"
#include "tree/cost.h"
#include "tree/leaf_thinning.h"
#include "tree/parameters.h"
#include "tree/template_file.h"
#include "tree/template_library.h"
#include "ui/state/leaves_only.h"
#include "ui/state/thread_priority.h"

namespace sylva::studio {
namespace {

using Clock = std::chrono::steady_clock;

bool ready(const auto& future) {
    return future.valid() && future.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

// The wind's parameters move a tree without shaping it: the view and the export read them
// from the template as it is, so with `wind` false they are left out.
bool same_params(const TreeParams& a, const TreeParams& b, bool wind) {
    if (a.seed != b.seed) return false;
    for (const ParamInfo& info : param_infos())
        if ((wind || info.group != ParamGroup::Wind) &&
            *get_param(a, info.key) != *get_param(b, info.key))
            return false;
    return true;
}

// What shapes the tree: a change here needs a new generation (a colour or a wind change
// does not).
bool same_tree_input(const TreeTemplate& a, const TreeTemplate& b) {
    return a.growth == b.growth && a.grammar == b.grammar && a.mode == b.mode &&
           a.width_model == b.width_model && same_params(a.params, b.params, false);
}

// The meshers get every core: while a worker runs, the UI thread draws only when woken or
// at a tenth of its usual rate (ui/main.cpp), so it keeps up without a core of its own.
int worker_threads() {
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Hands a tree to the UI before the job ends (poll_jobs shows it) and wakes the UI.
void hand_over(JobProgress& progress, std::shared_ptr<const GeneratedTree> tree) {
    {
        const std::lock_guard lock(progress.draft_mutex);
        progress.draft_tree = std::move(tree);
    }
    if (progress.wake) progress.wake();
}

// The worker: the whole pipeline (or the shown tree's meshes, `base`), then the export's
// LOD chain when a budget is given: the shown tree's own when the meshes came out the same
// (reuse_reduction()), reduced otherwise. While a slider is held the meshes are handed over
// as a draft first; level 0 of the game mesh is handed over before the further levels.
GeneratedTree generate(const TreeTemplate& tree_template, std::size_t budget,
                       const std::shared_ptr<JobProgress>& progress,
                       const std::shared_ptr<const GeneratedTree>& base,
                       const std::shared_ptr<const GeneratedTree>& leaves_base,
                       const std::shared_ptr<const GeneratedTree>& previous) {
    GeneratedTree out;
    std::optional<Tree> releaved;
    if (leaves_base)
        releaved = with_new_leaves(leaves_base->tree, tree_template, &progress->cancel);
    if (base) {
        out.tree = base->tree;
    } else if (releaved) {
        out.tree = std::move(*releaved);
    } else {
        MeshOptions options;
        options.threads = worker_threads();
        // The crown as the export at the template's budget meshes it, low-poly view or not.
        options.budget =
            static_cast<std::size_t>(std::max(tree_template.params.triangle_budget, 0));
        options.cancel = &progress->cancel;
        options.growth_progress = [&progress](float f) { progress->fraction = f; };
        options.progress = [&progress](float f) {
            progress->stage = JobProgress::Meshing;
            progress->fraction = f;
        };
        out.tree = generate_tree(tree_template, options);
    }
    if (budget == 0) return out;
    progress->fraction = 0.0f;
    const Clock::time_point start = Clock::now();
    if (previous) {
        if (std::optional<FinishedTree> kept = reuse_reduction(*previous, out.tree, budget)) {
            out.finished = std::move(*kept);
            out.budget = budget;
            out.reduction_reused = true;
            out.reduce_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            return out;
        }
    }
    if (progress->draft && !base) {
        auto draft = std::make_shared<GeneratedTree>();
        draft->tree = out.tree;
        draft->draft = true;
        hand_over(*progress, std::move(draft));
    }
    // After the draft: a job that reduces is cancelled by a newer value of a held slider.
    progress->stage = JobProgress::Reducing;
    FinishSettings finish;
    finish.budget.total = budget;
    finish.lod = true;
    finish.lod_levels = kLodLevels;
    finish.decimate.cancel = &progress->cancel;  // a newer edit stops a long reduction too
    finish.decimate.progress = [&progress](float f) { progress->fraction = f; };
    // Level 0 first, handed over to be shown (half the chain's time on a willow: the coarser
    // levels' crown hulls are made from the whole crown), then the rest of the chain from it.
    FinishSettings level0 = finish;
    level0.lod = false;
    FinishedTree first = finish_tree(out.tree, level0);
    if (!first.levels.empty()) {
        auto partial = std::make_shared<GeneratedTree>();
        partial->tree = out.tree;
        partial->finished = first;
        partial->budget = budget;
        partial->reduce_ms =
            std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        hand_over(*progress, std::move(partial));
    }
    finish.decimate.progress = nullptr;
    out.finished =
        finish_tree(out.tree, finish,
                    first.levels.empty() ? std::nullopt
                                         : std::optional<ReducedTree>(std::move(first.levels[0])));
    out.budget = budget;
    out.reduce_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return out;
}

// Runs generate() on a thread of its own: the result is set before the UI is woken, so the
// loop that wakes finds it ready.
GenerationJob launch(GenerationJob job) {
    std::promise<GeneratedTree> promise;
    job.result = promise.get_future();
    job.worker = std::jthread([promise = std::move(promise), tree_template = job.tree_template,
                               budget = job.budget, progress = job.progress, base = job.base,
                               leaves_base = job.leaves_base, previous = job.previous]() mutable {
        lower_thread_priority();  // the UI's frames first (ui/state/thread_priority.h)
        try {
            promise.set_value(
                generate(tree_template, budget, progress, base, leaves_base, previous));
        } catch (...) {
            promise.set_exception(std::current_exception());
        }
        // The fence pairs with start_generation's: either it sees this job ended or this
        // job sees that it was asked to wake the UI.
        std::atomic_thread_fence(std::memory_order_seq_cst);
        if (progress->wake && (!progress->cancel || progress->wake_when_cancelled))
            progress->wake();
    });
    return job;
}

void apply_edit(StudioState& state, const TreeTemplate& edit) {
    const bool other_tree = edit.name != state.tree_template.name;
    state.tree_template = edit;
    state.committed = edit;
    state.frame_next_tree |= other_tree;
    // A colour's undo needs no new tree (poll_jobs hands the colours to the tree on screen).
    if (!state.tree || edit_pending(state)) start_generation(state);
}

std::string files_text(const std::vector<std::filesystem::path>& files) {
    std::string text;
    for (const auto& file : files) text += (text.empty() ? "" : ", ") + file.string();
    return text;
}

// The export, on a worker: trunk and crown reduced to `budget` (0 keeps every triangle),
// or a LOD chain; returns the message the panel shows. The preview's reduction is reused
// when it has the same budget.
// `make_folder`: the path's folder is made first (core/output_folder.h) and removed again
// when the export fails, so a failed export leaves no empty folder behind.
std::string export_tree(const std::shared_ptr<const GeneratedTree>& shown, const TreeTemplate& tmpl,
                        std::size_t budget, const ExportSettings& settings, bool make_folder) {
    std::optional<OutputFolder> folder;
    if (make_folder) folder.emplace(std::filesystem::path(settings.path).parent_path());
    const Tree& tree = shown->tree;
    FinishedTree finished;
    if (budget > 0 && shown->reduced() && shown->budget == budget &&
        (!settings.lod || shown->finished.lod)) {
        // The view's chain is the export's: the whole of it, or level 0 alone.
        finished = shown->finished;
        if (!settings.lod) {
            finished.levels.resize(1);
            finished.budgets.resize(1);
            finished.leaf_budgets.resize(1);
            finished.lod = false;
        }
    } else {
        FinishSettings finish;
        finish.budget.total = budget;
        finish.lod = settings.lod;
        finished = finish_tree(tree, finish);
    }
    ExportOptions options;
    options.profile = settings.profile;
    options.engine.seed = tmpl.params.seed;
    options.material_prefix = material_prefix(tmpl.name, tmpl.params.seed);
    options.engine.wind_motion = wind_motion(tmpl.params);
    const auto files = write_tree(settings.path, tree, finished, tree_colors(tmpl), options);
    if (folder) folder->keep();
    if (finished.lod)
        return "wrote " + files_text(files) + ": LOD0-LOD" +
               std::to_string(finished.levels.size() - 1) + ", " +
               std::to_string(finished.budgets.front()) + " to " +
               std::to_string(finished.budgets.back()) + " trunk + crown triangles";
    const ModelParts parts = finished_parts(tree, finished, tree_colors(tmpl)).front();
    std::string text = "wrote " + files_text(files) + ":";
    for (const NamedMesh& part : parts)
        text += " " + part.name + " " + std::to_string(part.mesh->triangles.size()) + ",";
    text.back() = ' ';
    text += "triangles";
    if (!finished.levels.empty() && !finished.levels[0].note.empty())
        text += " (" + finished.levels[0].note + ")";
    return text;
}

// Template files are TOML (app/template_file.h); a .lsys or .txt name saves the grammar
// alone, which `-t` and Open read back as a bare grammar with default parameters.
void write_template(const std::filesystem::path& path, const TreeTemplate& tree,
                    std::string_view original_text) {
    const std::string ext = path.extension().string();
    if (ext == ".lsys" || ext == ".txt")
        write_file_atomically(path, [&](std::ostream& out) { out << tree.grammar; });
    else
        save_template_file(path, tree, original_text);
}

void save_recent_files(const StudioState& state) {
    if (state.recent_store.empty()) return;
    try {
        std::filesystem::create_directories(
            std::filesystem::path(state.recent_store).parent_path());
        write_file_atomically(state.recent_store, [&](std::ostream& out) {
            for (const std::string& file : state.recent_files) out << file << "\n";
        });
    } catch (const std::exception&) {
        // A list of recent files is a convenience: failing to keep it is not worth a message.
    }
}

// The crown a tree should have but did not get: tips, a sphere diameter and crown meshing
// on, and no crown triangles. The usual reason is a tree scaled up until the crown's grid
// cells are larger than its spheres.
std::string crown_notice_for(const Tree& tree, const TreeParams& p) {
    if (!tree.crown.triangles.empty() || !p.crown_mesh || p.sphere_diameter <= 0.0 ||
        tree.skeleton.segments.empty())
        return {};
    const Box box = skeleton_bounds(tree.skeleton);
    const glm::vec3 size = box.max - box.min;
    const double longest = std::max({size.x, size.y, size.z}) + p.sphere_diameter;
    const double cell = longest / std::max(p.crown_resolution, 1);
    char text[320];
    std::snprintf(text, sizeof text,
                  "The crown vanished: the tree is %.1f m across, so a crown grid cell is %.2f m, "
                  "too coarse for spheres of %.2f m. Raise sphere_diameter or crown_resolution.",
                  longest, cell, p.sphere_diameter);
    return text;
}

// Puts `generated` (made from `made_from`) on screen. When it is the game mesh, at the level
// viewed, of the value a slider was let go at, the release's time ends.
void show(StudioState& state, std::shared_ptr<const GeneratedTree> generated,
          TreeTemplate made_from) {
    state.tree = std::move(generated);
    state.shown_template = std::move(made_from);
    state.tree_changed = true;
    state.crown_notice = crown_notice_for(state.tree->tree, state.shown_template.params);
    state.error.clear();
    state.error_line = state.error_column = 0;
    const bool level_shown =
        static_cast<int>(state.tree->finished.levels.size()) > state.view.lod_level;
    if (state.released_at && state.tree->reduced() && !state.tree->draft && level_shown &&
        same_tree_input(state.shown_template, state.tree_template)) {
        state.release_ms =
            std::chrono::duration<double, std::milli>(Clock::now() - *state.released_at).count();
        state.released_at.reset();
    }
}

// Shows what the running job handed over since the last look: its draft, or its level 0
// before the further levels.
void show_draft(StudioState& state) {
    std::shared_ptr<const GeneratedTree> draft;
    {
        const std::lock_guard lock(state.job->progress->draft_mutex);
        draft = std::move(state.job->progress->draft_tree);
        state.job->progress->draft_tree.reset();
    }
    if (draft) show(state, std::move(draft), state.job->tree_template);
}

}  // namespace

bool same_template(const TreeTemplate& a, const TreeTemplate& b) {
    return same_tree_input(a, b) && same_params(a.params, b.params, true) && a.name == b.name &&
           a.description == b.description && a.colors.trunk == b.colors.trunk &&
           a.colors.crown == b.colors.crown && a.colors.leaves == b.colors.leaves;
}

bool same_mesh(const Mesh& a, const Mesh& b) {
    return a.positions == b.positions && a.triangles == b.triangles;
}

std::optional<FinishedTree> reuse_reduction(const GeneratedTree& previous, const Tree& tree,
                                            std::size_t budget) {
    if (!previous.reduced() || !previous.finished.lod || previous.budget != budget ||
        previous.tree.crown_shape != tree.crown_shape ||
        !same_mesh(previous.tree.trunk, tree.trunk) || !same_mesh(previous.tree.crown, tree.crown))
        return std::nullopt;
    FinishedTree finished = previous.finished;
    for (std::size_t i = 0; i < finished.levels.size(); ++i)
        finished.levels[i].leaves = game_leaves(tree, finished.leaf_budgets[i]);
    finished.organs = finished_organs(tree, finished.leaf_budgets);  // this tree's, not the last
    return finished;
}

ShownParts shown_parts(const GeneratedTree& generated, int level) {
    const std::vector<ReducedTree>& levels = generated.finished.levels;
    if (levels.empty())
        return {generated.tree.trunk, generated.tree.crown, generated.tree.leaves, 0};
    const int shown = std::clamp(level, 0, static_cast<int>(levels.size()) - 1);
    const ReducedTree& r = levels[static_cast<std::size_t>(shown)];
    return {r.trunk, r.crown, r.leaves, shown};
}

GameMeshTotals game_mesh_totals(const GeneratedTree& generated, int level) {
    assert(generated.reduced());
    const ShownParts parts = shown_parts(generated, level);
    const auto i = static_cast<std::size_t>(parts.level);
    const ReducedTree& reduced = generated.finished.levels[i];
    GameMeshTotals totals;
    totals.level = parts.level;
    totals.trunk = parts.trunk.triangles.size();
    totals.crown = parts.crown.triangles.size();
    totals.leaves = parts.leaves.triangles.size();
    totals.budget = generated.finished.budgets[i];
    totals.leaf_budget = generated.finished.leaf_budgets[i];
    totals.over_budget = !reduced.within_budget || totals.trunk + totals.crown > totals.budget ||
                         totals.leaves > totals.leaf_budget;
    totals.note = reduced.note;
    for (const std::string& note : generated.tree.notes)
        totals.note += (totals.note.empty() ? "" : "; ") + note;
    return totals;
}

std::string totals_text(const GameMeshTotals& t) {
    std::string text = "trunk " + std::to_string(t.trunk) + " + crown " + std::to_string(t.crown) +
                       " + leaves " + std::to_string(t.leaves) + " = " + std::to_string(t.total()) +
                       " triangles (budget " + std::to_string(t.budget);
    if (t.leaf_budget == SIZE_MAX)
        text += " + every leaf)";
    else
        text += " + " + std::to_string(t.leaf_budget) + " leaves)";
    return text;
}

bool draft_wanted(const StudioState& state) {
    return state.dragging && preview_budget(state) > 0;
}

void set_dragging(StudioState& state, bool dragging) {
    const bool released = state.dragging && !dragging;
    state.dragging = dragging;
    if (!released) return;
    // The job of the value let go at goes on to its game mesh without a draft, and its time
    // counts from now.
    if (state.job && state.job->progress->draft) {
        state.job->progress->draft = false;
        state.job->started = Clock::now();
    }
    // The value let go at waited for a job of the drag: it starts now, the older job goes.
    if (state.generate_wanted) {
        state.generate_wanted = false;
        start_generation(state);
    }
    if (!state.drag_edited) return;
    state.drag_edited = false;
    if (preview_budget(state) == 0) return;
    const bool shown = state.tree && state.tree->reduced() && !state.tree->draft &&
                       same_tree_input(state.shown_template, state.tree_template) &&
                       state.tree->budget == preview_budget(state) && !state.job;
    if (shown) {
        state.release_ms = 0;
        state.released_at.reset();
    } else {
        state.released_at = Clock::now();
    }
}

std::size_t preview_budget(const StudioState& state) {
    return state.view.low_poly
               ? static_cast<std::size_t>(std::max(state.tree_template.params.triangle_budget, 0))
               : 0;
}

void load_template_into(StudioState& state, const TreeTemplate& tree_template,
                        std::string_view text) {
    commit_edit(state);
    state.tree_template = tree_template;
    state.original = tree_template;
    state.original.source.clear();
    state.original.grammar_line = 1;
    state.saved = state.original;
    state.original_text =
        text.empty() ? std::string(builtin_template_text(tree_template.name)) : std::string(text);
    // The editor shows the grammar alone: errors count its lines, not the file's.
    state.tree_template.source.clear();
    state.tree_template.grammar_line = 1;
    commit_edit(state);  // picking a template is an edit: undo brings the old one back
    state.frame_next_tree = true;
    start_generation(state);
}

void reset_to_template(StudioState& state) {
    commit_edit(state);
    state.tree_template = state.original;
    commit_edit(state);
}

bool unsaved_changes(const StudioState& state) {
    return !same_template(state.tree_template, state.saved);
}

void set_colors(StudioState& state, const PartColors& colors) {
    state.tree_template.colors = colors;
    state.shown_template.colors = colors;
    if (state.job) state.job->tree_template.colors = colors;
}

void remember_file(StudioState& state, const std::string& path) {
    std::error_code ec;
    std::string absolute = std::filesystem::absolute(path, ec).lexically_normal().string();
    if (ec) absolute = path;
    std::erase(state.recent_files, absolute);
    state.recent_files.insert(state.recent_files.begin(), absolute);
    if (state.recent_files.size() > kMaxRecentFiles) state.recent_files.resize(kMaxRecentFiles);
    save_recent_files(state);
}

void load_recent_files(StudioState& state) {
    state.recent_files.clear();
    if (state.recent_store.empty()) return;
    std::ifstream in(state.recent_store);
    std::string line;
    while (std::getline(in, line) && state.recent_files.size() < kMaxRecentFiles)
        if (!line.empty()) state.recent_files.push_back(line);
}

void set_growth_method(StudioState& state, std::string_view method) {
    commit_edit(state);
    state.tree_template.growth = std::string(method);
    commit_edit(state);
}

bool asks_first(const StudioState& state, const Cost& cost) {
    return !within(cost, state.ask_limits) || cost.segments > state.ask_segments;
}

void start_generation(StudioState& state) {
    const bool draft = draft_wanted(state);
    const std::size_t budget = preview_budget(state);
    if (state.dragging) state.drag_edited = true;
    // The running job already makes this edit (a slider let go at the value its job was
    // started for): it goes on, without a draft once let go, and the time to the game mesh
    // counts from now.
    if (state.job && state.job->budget == budget &&
        same_tree_input(state.job->tree_template, state.tree_template)) {
        if (!draft && state.job->progress->draft) {
            state.job->progress->draft = false;
            state.job->started = Clock::now();
        }
        state.job->tree_template = state.tree_template;  // colours may have changed
        state.requested = state.tree_template;
        state.requested_budget = budget;
        state.generate_wanted = false;
        state.cost_warning.clear();  // it was for a value left since
        return;
    }
    // Rules applied on a typing pause are all this edit changed: a held-back estimate is
    // shown inline, without the dialog.
    const bool quiet = state.rules.quiet && state.tree_template.grammar != state.requested.grammar;
    state.requested = state.tree_template;
    state.requested_budget = budget;
    // A job the estimate puts over the limits (a very fine resolution, say) waits for "run
    // anyway"; the tree on screen stays.
    const Cost cost = estimate_cost(state.tree_template, budget);
    state.estimate = cost;
    if (asks_first(state, cost) && !state.run_costly) {
        char limits[128];
        std::snprintf(limits, sizeof limits, "%.0f segments, %.2g GB or %.2g s", state.ask_segments,
                      state.ask_limits.max_bytes / 1e9, state.ask_limits.max_seconds);
        state.cost_warning = "Not started: this tree is estimated at " + cost_text(cost) +
                             " at least, over the " + limits +
                             " a job may take unasked (the real time is often several times "
                             "the estimate).";
        state.cost_warning_quiet = quiet;
        return;
    }
    state.run_costly = false;
    state.cost_warning.clear();
    // Cancelling each step of a drag would show nothing while the slider moves: the drag's
    // job grows and meshes to its end and the newest value follows it (poll_jobs starts it).
    // Once it reduces, its draft is on screen and the reduction is for a value already left.
    if (state.dragging && state.job && state.job->during_drag) {
        if (state.job->progress->stage != JobProgress::Reducing) {
            state.generate_wanted = true;
            return;
        }
        show_draft(state);  // handed over since the last poll: on screen before it goes
    }
    if (state.job) {
        state.job->progress->cancel = true;
        state.stale.push_back(std::move(*state.job));
        state.job.reset();
    }
    // A cancelled job stops at its next check, which in some meshing phases is a second
    // away. The new job starts at once beside one or two winding down; past that it waits
    // (poll_jobs starts it), so a slider drag keeps at most three workers alive.
    constexpr std::size_t kMaxStale = 2;
    state.generate_wanted = state.stale.size() >= kMaxStale;
    if (state.generate_wanted) {
        // One may have ended before it was asked to wake the UI: poll_jobs starts the new
        // job at the next frame.
        for (GenerationJob& stale : state.stale) stale.progress->wake_when_cancelled = true;
        std::atomic_thread_fence(std::memory_order_seq_cst);
        bool ended = false;
        for (GenerationJob& stale : state.stale) ended |= ready(stale.result);
        if (ended && state.wake) state.wake();
        return;
    }

    state.job_estimate = cost;
    GenerationJob job;
    job.started = Clock::now();
    job.tree_template = state.tree_template;
    job.budget = budget;
    job.progress->draft = draft;
    job.progress->wake = state.wake;
    job.during_drag = state.dragging;
    // Only the reduction changes (low poly switched on, another budget): keep the meshes.
    if (state.tree && same_tree_input(state.shown_template, state.tree_template))
        job.base = state.tree;
    else if (state.tree && leaves_only_edit(state.shown_template, state.tree_template))
        job.leaves_base = state.tree;  // only the leaves are scattered again
    job.previous = state.tree;
    // The worker gets its own copies: editing while it runs is safe.
    state.job = launch(std::move(job));
}

bool generation_running(const StudioState& state) {
    return state.job.has_value() || state.generate_wanted;
}

void cancel_generation(StudioState& state) {
    state.generate_wanted = false;
    if (!state.job) return;
    state.job->progress->cancel = true;
    state.stale.push_back(std::move(*state.job));
    state.job.reset();
}

void cancel_generations(StudioState& state) {
    if (state.job) state.job->progress->cancel = true;
    for (GenerationJob& job : state.stale) job.progress->cancel = true;
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
    if (state.job && !ready(state.job->result)) show_draft(state);
    if (state.job && ready(state.job->result)) {
        GenerationJob job = std::move(*state.job);
        state.job.reset();
        state.last_wall_ms =
            std::chrono::duration<double, std::milli>(Clock::now() - job.started).count();
        try {
            show(state, std::make_shared<const GeneratedTree>(job.result.get()),
                 std::move(job.tree_template));
        } catch (const GrammarError& e) {
            // The GUI's error boundary: bad input becomes a message; the last tree stays.
            state.error = e.what();
            state.error_line = e.line();
            state.error_column = e.column();
        } catch (const Cancelled&) {
        } catch (const std::exception& e) {
            state.error = e.what();
            state.error_line = state.error_column = 0;
        }
    }
    // Colours need no new tree: when the edit is the tree on screen but for its colours
    // (reset, undo or redo of a colour), the tree on screen takes them.
    if (state.tree && same_tree_input(state.shown_template, state.tree_template))
        state.shown_template.colors = state.tree_template.colors;
    if (state.generate_wanted && state.stale.empty()) {
        // The edit may have moved on while the workers wound down (or the drag's job ran):
        // generate the newest.
        state.generate_wanted = false;
        start_generation(state);
    }
    if (ready(state.export_job)) {
        try {
            state.export_message = state.export_job.get();
            state.export_failed = false;
        } catch (const std::exception& e) {
            state.export_message = std::string("export failed: ") + e.what();
            state.export_failed = true;
        }
    }
}

bool edit_pending(const StudioState& state) {
    return !same_tree_input(state.tree_template, state.requested) ||
           preview_budget(state) != state.requested_budget;
}

bool commit_edit(StudioState& state) {
    if (same_template(state.tree_template, state.committed)) return false;
    state.undo.push_back(std::move(state.committed));
    state.redo.clear();
    state.committed = state.tree_template;
    constexpr std::size_t kMaxUndo = 200;  // each step holds a grammar: keep memory bounded
    if (state.undo.size() > kMaxUndo) state.undo.erase(state.undo.begin());
    return true;
}

void undo(StudioState& state) {
    commit_edit(state);
    if (state.undo.empty()) return;
    state.redo.push_back(state.tree_template);
    TreeTemplate previous = std::move(state.undo.back());
    state.undo.pop_back();
    apply_edit(state, previous);
}

void redo(StudioState& state) {
    if (state.redo.empty()) return;
    state.undo.push_back(state.tree_template);
    TreeTemplate next = std::move(state.redo.back());
    state.redo.pop_back();
    apply_edit(state, next);
}

std::size_t export_budget(const StudioState& state) {
    const int budget = state.export_settings.budget;
    return static_cast<std::size_t>(
        std::max(budget < 0 ? state.tree_template.params.triangle_budget : budget, 0));
}

void keep_export_budget(StudioState& state) {
    if (state.export_settings.budget < 0) return;
    commit_edit(state);
    state.tree_template.params.triangle_budget = state.export_settings.budget;
    commit_edit(state);
    state.export_settings.budget = -1;
}

std::vector<BudgetLine> budget_lines(const GameMeshTotals& t) {
    const bool every_leaf = t.leaf_budget == SIZE_MAX;
    return {
        {"trunk", t.trunk, 0, false},
        {"crown", t.crown, 0, false},
        {"trunk + crown", t.trunk + t.crown, t.budget, t.trunk + t.crown > t.budget},
        {"leaves", t.leaves, t.leaf_budget, t.leaves > t.leaf_budget},
        {"total", t.total(), every_leaf ? SIZE_MAX : t.budget + t.leaf_budget, t.over_budget},
    };
}

void undo_refused_edit(StudioState& state) {
    undo(state);
    state.cost_warning.clear();
    state.cost_warning_quiet = false;
    state.frame_requested = true;
    state.frame_next_tree = true;
}

namespace {

// start_export(), and with `make_folder` the folder made on the worker (export_tree()).
void start_export_job(StudioState& state, bool make_folder) {
    if (!state.tree) {
        state.export_message = "nothing to export yet";
        state.export_failed = true;
        return;
    }
    if (state.export_job.valid()) return;  // one export at a time
    const std::filesystem::path folder =
        std::filesystem::path(state.export_settings.path).parent_path();
    std::error_code ec;
    if (!make_folder && !folder.empty() && !std::filesystem::is_directory(folder, ec)) {
        state.export_missing_folder = folder.string();
        state.export_message = "the folder " + folder.string() + " does not exist";
        state.export_failed = true;
        return;
    }
    state.export_missing_folder.clear();
    state.export_message = "exporting...";
    state.export_failed = false;
    const std::size_t budget = export_budget(state);
    state.export_job = std::async(std::launch::async, export_tree, state.tree, state.shown_template,
                                  budget, state.export_settings, make_folder);
}

}  // namespace

void start_export(StudioState& state) {
    start_export_job(state, false);
}

void create_export_folder(StudioState& state) {
    if (state.export_missing_folder.empty()) return;
    // The worker makes the folder (an IoError naming it when it cannot) and removes it
    // again when the export fails.
    start_export_job(state, true);
}

void save_template_to_file(StudioState& state) {
    try {
        write_template(state.template_path, state.tree_template, state.original_text);
        state.file_message = "saved " + state.template_path;
        state.file_failed = false;
        state.saved = state.tree_template;
        remember_file(state, state.template_path);
    } catch (const std::exception& e) {
        state.file_message = e.what();
        state.file_failed = true;
    }
}

void open_template_file(StudioState& state) {
    open_template_file(state, state.template_path);
}

void open_template_file(StudioState& state, const std::string& path) {
    try {
        TemplateSwitch next{load_template(path), {}, path};
        if (std::filesystem::path(path).extension() == ".toml")
            next.text = read_input_file(path, "template");
        if (!switch_template(state, std::move(next)))
            state.file_message = "unsaved changes: discard them to open " + path + "?";
    } catch (const std::exception& e) {
        state.file_message = e.what();
        state.file_failed = true;
    }
}

bool switch_template(StudioState& state, TemplateSwitch next) {
    if (unsaved_changes(state)) {
        state.pending_switch = std::move(next);
        return false;
    }
    state.pending_switch.reset();
    load_template_into(state, next.tree_template, next.text);
    if (!next.path.empty()) {
        // A grammar file: no comments to keep.
        if (next.text.empty() && std::filesystem::is_regular_file(next.path))
            state.original_text.clear();
        state.template_path = next.path;
        remember_file(state, next.path);
        state.file_message = "opened " + next.path;
        state.file_failed = false;
    }
    return true;
}

void confirm_switch(StudioState& state) {
    if (!state.pending_switch) return;
    TemplateSwitch next = std::move(*state.pending_switch);
    state.pending_switch.reset();
    state.saved = state.tree_template;  // the edits are dropped (undo keeps them)
    switch_template(state, std::move(next));
}

void cancel_switch(StudioState& state) {
    state.pending_switch.reset();
    state.file_message.clear();
}

}  // namespace sylva::studio
