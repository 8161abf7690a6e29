// Everything the studio shows and the panels edit: plain data, plus the background jobs
// (generation, export) that run off the UI thread. The window, GL objects and ImGui live in
// main; panels are functions of this state.
#pragma once

#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "export/export_tree.h"
#include "tree/pipeline.h"
#include "ui/orbit_camera.h"

namespace sylva::studio {

// True when the two templates are the same edit: grammar, turtle, widths, parameters, seed,
// colours, name. What undo / redo step through.
bool same_template(const TreeTemplate& a, const TreeTemplate& b);

// A finished generation: the tree, and with the low-poly view its trunk and crown reduced to
// the triangle budget, as an export with that budget writes them.
struct GeneratedTree {
    Tree tree;
    // Trunk and crown as shown, and as an export with `budget` writes them; no levels: the
    // marching-cubes meshes (the low-poly view is off).
    FinishedTree finished;
    std::size_t budget = 0;  // what `finished` was reduced to
    bool reduced() const { return !finished.levels.empty(); }
    double reduce_ms = 0;
};

// What a worker reports while it runs; shared with it, so it outlives a cancelled job.
struct JobProgress {
    enum Stage { Growing, Meshing, Reducing };
    std::atomic<bool> cancel{false};
    std::atomic<int> stage{Growing};
    std::atomic<float> fraction{0.0f};  // of the current stage
};

// A generation on a worker thread. Cancelling only asks; the job is kept until its future is
// ready (a std::async future blocks in its destructor), so the UI thread never waits for it.
struct GenerationJob {
    std::future<GeneratedTree> result;
    std::shared_ptr<JobProgress> progress = std::make_shared<JobProgress>();
    std::chrono::steady_clock::time_point started;
    TreeTemplate tree_template;  // what it generates (and the colours it is drawn with)
    std::size_t budget = 0;      // 0: no low-poly reduction
};

struct ViewToggles {
    bool skeleton = false;
    bool trunk = true;
    bool crown = true;
    bool leaves = true;
    bool wireframe = false;
    bool low_poly = false;  // show trunk and crown reduced to the triangle budget
};

// The export's own settings; the triangle budget is the template's `triangle_budget`.
struct ExportSettings {
    std::string path = "tree.glb";  // the extension picks the format: .obj, .glb, .ply
    bool lod = false;
};

struct StudioState {
    TreeTemplate tree_template;  // what the panels edit
    // The last good tree, on screen. Shared so an export can read it on a worker without a copy.
    std::shared_ptr<const GeneratedTree> tree;
    TreeTemplate shown_template;  // the template of the tree on screen
    bool tree_changed = false;    // set when `tree` was replaced; main uploads and clears it

    std::optional<GenerationJob> job;  // the generation whose result will be shown
    std::vector<GenerationJob> stale;  // cancelled generations still finishing
    TreeTemplate requested;            // what the last started generation is for
    std::size_t requested_budget = 0;  // ... and the budget it reduces to
    bool generate_wanted = false;      // a start deferred until the cancelled jobs finished
    double last_wall_ms = 0;
    bool live = true;  // regenerate on every edit

    // The last generation's error; grammar errors also carry the line and column (1-based).
    std::string error;
    int error_line = 0, error_column = 0;

    // Undo history: whole templates, so picking another template can be undone too.
    std::vector<TreeTemplate> undo, redo;
    TreeTemplate committed;  // the edit undo would step back from

    std::string template_path = "my_tree.toml";  // Open / Save as
    std::string file_message;                    // result of the last open or save
    bool file_failed = false;

    ExportSettings export_settings;
    std::future<std::string> export_job;  // the export's result message
    std::string export_message;
    bool export_failed = false;

    ViewToggles view;
    OrbitCamera camera;
    bool frame_requested = false;  // frame the tree on screen now ("frame tree", F)
    bool frame_next_tree = true;   // frame the next tree that arrives (a new template)
    bool quit_requested = false;
};

// The budget trunk and crown are shown at: the template's triangle_budget with the low-poly
// view on, 0 (the marching-cubes meshes) otherwise.
std::size_t preview_budget(const StudioState& state);

// Replaces the edited template (an undoable edit) and frames the tree it makes.
void load_template_into(StudioState& state, const TreeTemplate& tree_template);

// Cancels the running generation, if any, and starts one of the edited template. While two
// cancelled jobs still wind down, the start waits (generate_wanted), so dragging a slider
// never piles up workers.
void start_generation(StudioState& state);

bool generation_running(const StudioState& state);

// Asks every running generation to stop (on exit).
void cancel_generations(StudioState& state);

// Takes finished jobs without blocking: a finished generation replaces `tree` (or sets
// `error`, keeping the last good tree), a finished export sets `export_message`.
void poll_jobs(StudioState& state);

// True when the edited template differs from what was last generated in what shapes the tree.
bool edit_pending(const StudioState& state);

// Records an edit into the undo history once the template differs from the last committed
// one; call when no widget is being dragged or typed into. Returns true when there was one.
bool commit_edit(StudioState& state);
void undo(StudioState& state);
void redo(StudioState& state);

// Writes the tree on screen to export_settings.path on a worker thread, reduced to the edited
// template's triangle_budget.
void start_export(StudioState& state);

// Saves the edited template to template_path; loads one from it. Messages go to file_message.
void save_template_to_file(StudioState& state);
void open_template_file(StudioState& state);

}  // namespace sylva::studio
