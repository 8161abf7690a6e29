// Everything the studio shows and the panels edit: plain data, plus the background jobs
// (generation, export) that run off the UI thread. The window, GL objects and ImGui live in
// main; panels are functions of this state.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "export/export_tree.h"
#include "export/wind_motion.h"
#include "tree/cost.h"
#include "tree/pipeline.h"
#include "ui/state/forest_preview_plan.h"
#include "ui/state/orbit_camera.h"
#include "ui/state/rules_draft.h"

namespace sylva::studio {

// True when the two templates are the same edit: grammar, turtle, widths, parameters, seed,
// colours, name. What undo / redo step through.
bool same_template(const TreeTemplate& a, const TreeTemplate& b);

// LOD levels the low-poly view offers: the chain an export with "LOD chain" writes.
constexpr int kLodLevels = 4;

// A finished generation: the tree, and with the low-poly view the game mesh an export with
// that budget writes, as a LOD chain (level 0 is the plain export).
struct GeneratedTree {
    Tree tree;
    // The export's LOD chain at `budget` (FinishSettings{.lod = true}): trunk, crown and
    // thinned leaves per level. No levels: the marching-cubes meshes and every leaf (the
    // low-poly view is off, or this is a draft).
    FinishedTree finished;
    std::size_t budget = 0;  // what `finished` was reduced to
    // The raw meshes of a job whose reduction still runs (a slider is held): they stand in
    // until the game mesh follows.
    bool draft = false;
    bool reduced() const { return !finished.levels.empty(); }
    double reduce_ms = 0;
    // Trunk and crown came out of the meshing exactly as the tree shown before had them at
    // the same budget (a leaf, seed-of-leaves or colour edit): its reduction was kept and
    // only the leaves thinned again.
    bool reduction_reused = false;
};

// True when the two meshes are the same bytes (positions and triangles).
bool same_mesh(const Mesh& a, const Mesh& b);

// The game mesh `previous` shows, made again for `tree` without reducing: its reduced trunk
// and crown when `tree`'s trunk and crown are the ones it was reduced from (same bytes) and
// the budget and the crown shape are the same, with `tree`'s leaves thinned per level. Empty
// (nothing reused) otherwise. What a reduction would give, as the reduction is deterministic.
std::optional<FinishedTree> reuse_reduction(const GeneratedTree& previous, const Tree& tree,
                                            std::size_t budget);

// The meshes the view draws for LOD `level` (clamped to the levels there are): that level's
// trunk, crown and thinned leaves when reduced, the tree's own otherwise. Exactly the parts an
// export of that level writes.
struct ShownParts {
    const Mesh& trunk;
    const Mesh& crown;
    const Mesh& leaves;
    int level;  // the level shown; 0 when not reduced
};
ShownParts shown_parts(const GeneratedTree& generated, int level);

// Triangles of one level of the game mesh against its budgets, for the status bar and export.
struct GameMeshTotals {
    int level = 0;
    std::size_t trunk = 0, crown = 0, leaves = 0;
    std::size_t budget = 0;       // trunk + crown
    std::size_t leaf_budget = 0;  // SIZE_MAX: every leaf
    bool over_budget = false;     // a part over its share, or the reducer missed the budget
    std::string note;             // the reducer's: why the budget was missed / what backed off
    std::size_t total() const { return trunk + crown + leaves; }
};
// Needs a reduced tree.
GameMeshTotals game_mesh_totals(const GeneratedTree& generated, int level);

// One line of the budget table: a part's triangles against its target. Trunk and crown
// share one target, shown on their own "trunk + crown" line; leaves have theirs; the total
// is the sum of both.
struct BudgetLine {
    std::string part;  // "trunk", "crown", "trunk + crown", "leaves", "total"
    std::size_t triangles = 0;
    std::size_t target = 0;  // 0: none of its own (trunk, crown); SIZE_MAX: every leaf
    bool over = false;
};
std::vector<BudgetLine> budget_lines(const GameMeshTotals& totals);
// "trunk 484 + crown 316 + leaves 800 = 1600 triangles (budget 800 + 800 leaves)".
std::string totals_text(const GameMeshTotals& totals);

// What a worker reports while it runs; shared with it, so it outlives a cancelled job.
struct JobProgress {
    enum Stage { Growing, Meshing, Reducing };
    std::atomic<bool> cancel{false};
    std::atomic<int> stage{Growing};
    std::atomic<float> fraction{0.0f};  // of the current stage
    // A slider is held: once the meshes are made, hand them over as a draft (draft_tree)
    // before the reduction starts. Cleared when the slider is let go (the game mesh follows
    // without a draft in between).
    std::atomic<bool> draft{false};
    std::mutex draft_mutex;
    // What the worker hands over before it ends (the draft, then level 0 of the game mesh);
    // guarded by draft_mutex; taken by poll_jobs.
    std::shared_ptr<const GeneratedTree> draft_tree;
    // Called by the worker when it has something to show (a draft, its result): main wakes
    // its event loop with it, which waits while only workers run.
    std::function<void()> wake;
    // A cancelled job ends without waking the UI (a frame drawn for nothing takes the
    // cores from the job that replaced it), unless a newer job waits for it to end.
    std::atomic<bool> wake_when_cancelled{false};
};

// A generation on a worker thread. Cancelling only asks; the job is kept until its future is
// ready (its thread is joined when the job goes), so the UI thread never waits for it.
struct GenerationJob {
    std::future<GeneratedTree> result;
    std::jthread worker;  // sets `result`, then wakes the UI
    std::shared_ptr<JobProgress> progress = std::make_shared<JobProgress>();
    std::chrono::steady_clock::time_point started;
    TreeTemplate tree_template;  // what it generates (and the colours it is drawn with)
    std::size_t budget = 0;      // 0: no low-poly reduction
    // The tree on screen when it is the same tree (only the reduction changes): its meshes
    // are reused and only the reduction runs.
    std::shared_ptr<const GeneratedTree> base;
    bool during_drag = false;  // started while a slider was held
    // The tree on screen when only the leaves' parameters changed: its skeleton, trunk and
    // crown are kept and only the leaves scattered again (ui/state/leaves_only.h).
    std::shared_ptr<const GeneratedTree> leaves_base;
    // The tree on screen when the job started: a job whose trunk and crown come out the same
    // reuses its reduction (reuse_reduction()).
    std::shared_ptr<const GeneratedTree> previous;
};

struct ViewToggles {
    bool skeleton = false;
    bool trunk = true;
    bool crown = true;
    bool leaves = true;
    bool wireframe = false;
    bool low_poly = false;  // show the game mesh: what an export at the budget writes
    int lod_level = 0;      // which level of the LOD chain the low-poly view shows
    // At the slider's impostor slot (ui/impostor_view.h): the tree it stands for instead.
    bool impostor_tree = false;
    // Space colonization trees only (ui/state/colonization_view.h):
    bool envelope = true;      // the envelope as a wire cage
    bool points = false;       // the attraction points the growth started from
    bool replay = false;       // the skeleton after growth step replay_iteration, no meshes
    int replay_iteration = 0;  // clamped to the tree's last step when drawn
    // Sway the tree with its exported wind data (ui/state/wind_view.h) in the template's
    // wind (core/wind_params.h).
    bool wind = false;
    bool scale_figure = true;  // a 1.8 m person beside the trunk, for scale
    bool turntable = false;    // the camera circles the tree
    // A small square of forest planted with the shown template (ui/forest_preview.h).
    bool forest = false;
    ForestPreviewOptions forest_options;
    ForestPreviewPlan forest_plan;  // a 2D layout planted instead of the square (layout panel)
};

// The export's own settings, apart from the template's: changing them is no edit of the
// template (keep_export_budget() makes the budget the template's).
struct ExportSettings {
    std::string path = "tree.glb";  // the extension picks the format: .obj, .glb, .ply
    // Trunk + crown triangles an export reduces to (0: every triangle); negative: the edited
    // template's triangle_budget, whatever template is picked.
    int budget = -1;
    bool lod = false;
    EngineProfile profile = EngineProfile::Generic;  // export/engine_profile.h
};

// Another template to edit: a built-in one, or one read from `path`.
struct TemplateSwitch {
    TreeTemplate tree_template;
    std::string text;  // the file text it was read from (a built-in template's own when empty)
    std::string path;  // the file it was opened from; empty for a built-in template
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
    bool dragging = false;             // a slider is held (set_dragging() each frame): drafts first
    // The time from letting go of a slider that edited the tree to its game mesh arriving
    // (the status bar's "release -> game mesh"); negative before the first. 0 when the game
    // mesh was on screen before the slider was let go.
    double release_ms = -1;
    std::optional<std::chrono::steady_clock::time_point> released_at;  // still waiting
    bool drag_edited = false;  // the held slider started a generation
    // Wakes main's event loop from a worker (glfwPostEmptyEvent); empty headless.
    std::function<void()> wake;
    bool generate_wanted = false;  // a start deferred until the cancelled jobs finished
    double last_wall_ms = 0;
    bool live = true;  // regenerate on every edit

    // The last generation's error; grammar errors also carry the line and column (1-based).
    std::string error;
    int error_line = 0, error_column = 0;

    // An edit estimated over the cost limits (tree/cost.h) does not start a generation: the
    // estimate is shown, and "run anyway" sets run_costly and starts it once.
    std::string cost_warning;  // empty: nothing held back
    // The warning came from rules applied on a typing pause: it is shown beside the editor and
    // the dialog does not open (it would take the keyboard mid-word) until the user applies
    // explicitly (Ctrl+Enter).
    bool cost_warning_quiet = false;
    bool run_costly = false;
    // Where the studio asks first: over the CLI's limits, or over ask_segments skeleton
    // segments. The time estimate is a lower bound that misses most of what many segments
    // cost (the oak at generations 12 takes many times its estimate), so the segment count
    // asks well before the time limit would; every built-in template's default stays under
    // both (tests/ui checks).
    CostLimits ask_limits;
    double ask_segments = 10000;
    // The estimate of the edited template (before any job starts) and of the running job,
    // for the size line and the progress bar's time left.
    Cost estimate;
    Cost job_estimate;

    // The template as it was opened or picked (reset, the slider ranges) and the file text it
    // came from (its comments are written again on save; empty when there is none).
    TreeTemplate original;
    std::string original_text;
    TreeTemplate saved;  // as last saved or opened: the unsaved-changes mark compares with it
    std::vector<std::string> recent_files;  // newest first, at most kMaxRecentFiles
    std::string recent_store;               // where they persist ("": not at all)

    // Said when a tree arrives whose crown vanished although it should have one (scaled up
    // past the crown grid's cells, say); empty otherwise.
    std::string crown_notice;

    // The rules editor's text, applied to tree_template.grammar on a pause (rules_draft.h).
    RulesDraft rules;

    // Undo history: whole templates, so picking another template can be undone too.
    std::vector<TreeTemplate> undo, redo;
    TreeTemplate committed;  // the edit undo would step back from

    // A switch to another template waiting for "discard changes?" (switch_template()).
    std::optional<TemplateSwitch> pending_switch;

    std::string template_path = "my_tree.toml";  // Open / Save as
    std::string file_message;                    // result of the last open or save
    bool file_failed = false;

    ExportSettings export_settings;
    std::future<std::string> export_job;  // the export's result message
    // The folder of export_settings.path when it does not exist: nothing was written, and
    // the Export section asks to create it (create_export_folder()). Empty otherwise.
    std::string export_missing_folder;
    std::string export_message;
    bool export_failed = false;

    std::string parameter_search;  // the Tree panel's search field: shows what matches

    ViewToggles view;
    OrbitCamera camera;
    bool frame_requested = false;  // frame the tree on screen now ("frame tree", F)
    bool frame_next_tree = true;   // frame the next tree that arrives (a new template)
    bool quit_requested = false;
    // "screenshot": main saves the 3D view as a PNG after the next frame is drawn.
    bool screenshot_requested = false;
    std::string screenshot_message;
    bool show_shortcuts = false;    // the list of keys (F1, "?")
    std::string forest_status;      // the forest preview's progress or error, for the View row
    bool layout_requested = false;  // the View row's "2D layouts" button (a build with layout/)
};

// True when the next generation should show a draft: the low-poly view is on and a slider
// is held, so the raw meshes are shown as soon as they are made, and the reduction follows
// (cancelled when the slider moves on).
bool draft_wanted(const StudioState& state);

// Main's per-frame "a slider is held". Letting go of one that edited the tree starts the
// release clock (release_ms).
void set_dragging(StudioState& state, bool dragging);

// The budget trunk and crown are shown at: the template's triangle_budget with the low-poly
// view on, 0 (the marching-cubes meshes) otherwise.
std::size_t preview_budget(const StudioState& state);

// Replaces the edited template (an undoable edit) and frames the tree it makes. `text` is the
// file text it was read from (its comments are kept on save); a built-in template's own.
void load_template_into(StudioState& state, const TreeTemplate& tree_template,
                        std::string_view text = {});

// Makes `next` the edited template (load_template_into, and for a file its path, the recent
// files and the message), unless the edited template has unsaved changes: then it waits in
// pending_switch for the "discard changes?" dialog and false is returned.
bool switch_template(StudioState& state, TemplateSwitch next);
// The dialog's answers: switch and drop the edits (undo still brings them back), or keep
// editing.
void confirm_switch(StudioState& state);
void cancel_switch(StudioState& state);

// Back to the template as it was opened or picked: an undoable edit.
void reset_to_template(StudioState& state);

// True when the edited template differs from the one last saved or opened.
bool unsaved_changes(const StudioState& state);

// Sets the part colours of the edited template and of the tree on screen (a colour change
// needs no new tree).
void set_colors(StudioState& state, const PartColors& colors);

constexpr std::size_t kMaxRecentFiles = 8;
// Puts `path` first in the recent files (and their store, when set).
void remember_file(StudioState& state, const std::string& path);
// Reads the recent files from state.recent_store (missing: none).
void load_recent_files(StudioState& state);

// Switches the edited template's growth method (a name from tree/growth.h's
// growth_methods()): an undoable edit, committed at once like picking a template.
void set_growth_method(StudioState& state, std::string_view method);

// Cancels the running generation, if any, and starts one of the edited template. While two
// cancelled jobs still wind down, the start waits (generate_wanted), so dragging a slider
// never piles up workers. While a slider is held a job of the drag is not cancelled while
// it grows and meshes: the newest value waits for it (generate_wanted), so a moving slider
// still shows a tree every job's time rather than none until it pauses; with the low-poly
// view on those jobs show their meshes as a draft and then reduce, and a job that is
// reducing is cancelled by a newer value (its draft is on screen). So a slider held still
// gets its game mesh while it is held, and on release a running job of the same value is
// kept: only what is left of its work stands between the release and the game mesh.
void start_generation(StudioState& state);

bool generation_running(const StudioState& state);

// True when a job of this estimated cost waits for "run anyway" (ask_limits, ask_segments).
bool asks_first(const StudioState& state, const Cost& cost);

// Stops the running generation (a cancel button, Esc); the tree on screen stays, and the
// edit is not generated again until the next edit or Generate.
void cancel_generation(StudioState& state);

// Asks every running generation to stop (on exit).
void cancel_generations(StudioState& state);

// Takes finished jobs without blocking: a finished generation replaces `tree` (or sets
// `error`, keeping the last good tree), a finished export sets `export_message`.
void poll_jobs(StudioState& state);

// True when the edited template differs from what was last generated in what shapes the tree,
// or in the budget shown.
bool edit_pending(const StudioState& state);

// Records an edit into the undo history once the template differs from the last committed
// one; call when no widget is being dragged or typed into. Returns true when there was one.
bool commit_edit(StudioState& state);
void undo(StudioState& state);
void redo(StudioState& state);

// "Undo the edit" of an edit held back by its estimated cost: undo(), the warning dropped,
// and the camera frames the tree on screen now and the tree the undo brings back.
void undo_refused_edit(StudioState& state);

// The trunk + crown triangles an export reduces to: export_settings.budget, or the edited
// template's triangle_budget when that is negative.
std::size_t export_budget(const StudioState& state);

// Makes the export's budget the edited template's triangle_budget (an undoable edit that a
// save writes) and lets the export follow the template again.
void keep_export_budget(StudioState& state);

// Writes the tree on screen to export_settings.path on a worker thread, reduced to
// export_budget(); the low-poly view's chain is reused when its budget matches. A path whose
// folder does not exist writes nothing: export_missing_folder names it, for the panel to ask.
void start_export(StudioState& state);

// Starts the export held back by a missing folder; its worker makes the folder and the ones
// above it (core/output_folder.h: removed again when the export fails, so a failed export
// leaves no empty folder). The message names the folder when it cannot be made.
void create_export_folder(StudioState& state);

// Saves the edited template to template_path; loads one from it. Messages go to file_message.
void save_template_to_file(StudioState& state);
// Opening asks first when the edited template has unsaved changes (switch_template()).
void open_template_file(StudioState& state);
void open_template_file(StudioState& state, const std::string& path);

}  // namespace sylva::studio
