// The studio's layout panel (layout/): open a 2D example (a shipped one, or any .mesh / .json
// file by the file dialog or by dropping it on the window), see the grammar derived from it
// (primitives and rules as small pictures), a strip of variations grown to a target size,
// plant the chosen one into the forest preview and export the planted forest as a glb.
// Deriving and generating run on a worker (a new example or setting cancels the running job);
// the panel keeps showing the last result meanwhile. Drawn with ImGui draw lists only.
#pragma once

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "layout/generate.h"
#include "layout/variations.h"
#include "ui/file_dialog.h"
#include "ui/panels.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {

// What one job made: the example, its grammar (as a growth table) and the variations.
struct LayoutResult {
    std::string source;  // the example's name or file
    int seed = 1, count = 12, size = 0;
    std::optional<layout::Example> input;
    std::shared_ptr<const layout::GrowthTable> table;
    std::vector<layout::PolygonMesh> starters;  // the starter rules, drawn
    std::vector<layout::PolygonMesh> variations;
    layout::VariationsReport report;
    double derive_ms = 0, generate_ms = 0;
    std::string error;
};

struct LayoutPanelState {
    bool open = false;
    std::string source = "village";  // a shipped example's name or a file
    int seed = 1;
    int count = 12;
    int size = 0;  // target size of the variations; 0: spread over 1 to 12 times the example's
    int selected = 0;
    std::shared_ptr<const LayoutResult> shown;
    std::future<std::shared_ptr<const LayoutResult>> job;
    std::shared_ptr<std::atomic<bool>> cancel;
    std::vector<std::future<std::shared_ptr<const LayoutResult>>> stale;  // cancelled, winding down
    LayoutResult job_settings;  // what the running job makes (source, seed, count, size)
    FileDialogState open_dialog, export_dialog;
    std::future<std::string> export_job;  // planting and writing a forest: its message
    std::shared_ptr<std::atomic<bool>> export_cancel;
    std::string message;
    bool message_failed = false;
    std::uint64_t planted = 0;      // plan ids given to the forest preview
    bool plant_when_ready = false;  // plant the first variation once there is one
};

// Opens the panel on a shipped example by name, or on a .mesh / .json file; false when it is
// neither.
bool select_layout_example(LayoutPanelState& state, const std::string& name_or_path);
// Opens a .mesh / .json file in the panel (a dropped or chosen file).
void open_layout_file(LayoutPanelState& state, const std::string& path);

// A floating window over the lower half of the 3D view (the forest planted from it shows
// above); nothing when the panel is closed. Planting a plan sets the forest preview's plan
// (`studio.view.forest_plan`) and switches the preview on.
void draw_layout_panel(LayoutPanelState& state, StudioState& studio, const PanelLayout& layout);

// Plants variation `selected` of the shown result into the forest preview and switches the
// preview on; false when there is none yet.
bool plant_layout(LayoutPanelState& state, StudioState& studio);

// Cancels the jobs and waits for them (before the window goes away).
void release_layout_panel(LayoutPanelState& state);

}  // namespace sylva::studio
