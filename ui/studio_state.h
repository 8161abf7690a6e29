// Everything the studio shows and the panels edit: plain data, plus the background jobs
// (generation, export) that run off the UI thread. The window, GL objects and ImGui live in
// main; panels are functions of this state.
#pragma once

#include "app/pipeline.h"
#include "ui/orbit_camera.h"

#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sylva::studio {

// What undo / redo restore: the grammar and the parameters.
struct Edit {
    std::string grammar;
    TreeParams params;
    bool operator==(const Edit&) const;
};

// A generation on a worker thread. Cancelling only asks; the job is kept until its future is
// ready, since a std::async future blocks in its destructor.
struct GenerationJob {
    std::future<Tree> result;
    std::shared_ptr<std::atomic<bool>> cancel = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<std::atomic<float>> progress = std::make_shared<std::atomic<float>>(0.0f);
    std::chrono::steady_clock::time_point started;
    TreeTemplate tree_template;  // what it generates (the colours it will be drawn with)
};

struct ViewToggles {
    bool skeleton = false;
    bool trunk = true;
    bool crown = true;
    bool leaves = true;
    bool wireframe = false;
    bool low_poly = false;  // show trunk and crown reduced to the export budget
};

struct ExportSettings {
    std::string path = "tree.glb";  // the extension picks the format: .obj, .glb, .ply
    int budget = 800;               // trunk + crown triangles; 0 keeps every triangle
    bool lod = false;
};

struct StudioState {
    TreeTemplate tree_template;  // what the panels edit
    std::optional<Tree> tree;    // the last good tree, on screen
    TreeTemplate shown_template; // the template of the tree on screen
    bool tree_changed = false;   // set when `tree` was replaced; main uploads and clears it

    std::optional<GenerationJob> job;  // the generation whose result will be shown
    Edit requested;                    // the edit the last started generation is for
    int requested_budget = 0;          // ... and the budget it reduces to (0: it does not)
    std::vector<GenerationJob> stale;  // cancelled generations still finishing
    double last_wall_ms = 0;
    bool live = true;  // regenerate on every edit

    // The last generation's error; grammar errors also carry the line and column (1-based).
    std::string error;
    int error_line = 0, error_column = 0;

    std::vector<Edit> undo, redo;
    Edit committed;  // the edit undo would step back from

    std::string template_path = "my_tree.toml";  // Open... / Save as...
    std::string file_message;                    // result of the last open or save

    ExportSettings export_settings;
    std::future<std::string> export_job;  // the export's result message
    std::string export_message;

    ViewToggles view;
    OrbitCamera camera;
    bool frame_requested = false;  // frame the tree on screen now ("frame tree", F)
    bool frame_next_tree = true;   // frame the next tree that arrives (a new template)
    bool quit_requested = false;
};

// Replaces the edited template (undo history restarts) and generates it.
void load_template_into(StudioState& state, const TreeTemplate& tree_template);

// Cancels the running generation, if any, and starts one of the edited template.
void start_generation(StudioState& state);

bool generation_running(const StudioState& state);

// Asks every running generation to stop (on exit).
void cancel_generations(StudioState& state);
float generation_progress(const StudioState& state);

// Takes finished jobs without blocking: a finished generation replaces `tree` (or sets
// `error`, keeping the last good tree), a finished export sets `export_message`.
void poll_jobs(StudioState& state);

// True when the edited grammar or parameters differ from what was last generated.
bool edit_pending(const StudioState& state);

// Records an edit into the undo history once the grammar or parameters differ from the last
// committed edit; call when no widget is being dragged. Returns true when there was one.
bool commit_edit(StudioState& state);
void undo(StudioState& state);
void redo(StudioState& state);

// Writes the tree on screen to export_settings.path on a worker thread.
void start_export(StudioState& state);

// Saves the edited template to template_path (TOML); loads one from it. Messages go to
// file_message.
void save_template_to_file(StudioState& state);
void open_template_file(StudioState& state);

}  // namespace sylva::studio
