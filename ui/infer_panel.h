// The studio's "Rules from a tree" window (docs/infer.md): derives an editable template from
// the tree on screen or from a skeleton file (skeleton.json, a cylinder table, an OBJ of
// line segments) on a worker thread, loads it into the editor as an undoable edit (so its
// #define sliders, the Variants strip and Export work on it as on any template), and draws
// the example's skeleton as lines beside the regrown tree or over it, with the fit report.
//
// Everything runs on the UI thread except the job (infer/ is thread-safe); the lines need
// the GL context, created with the first result.
#pragma once

#include <atomic>
#include <future>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "infer/fit_report.h"
#include "infer/rule_inference.h"
#include "ui/file_dialog.h"
#include "ui/line_renderer.h"
#include "ui/panels.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {

// What one derivation found.
struct InferOutcome {
    std::string source;  // "the oak on screen" or the file's path
    Skeleton example;    // the example as read, its branch depths filled in
    InferredTemplate inferred;
    FitReport report;
    double infer_ms = 0;  // reading and inference, without the regrowth
};

enum class InferOverlay { Beside, OnTop, Off };

struct InferPanel {
    bool open = false;  // the window shows (the View menu opens it, its close button closes it)
    int up = 0;         // a CSV's or OBJ's up axis: 0 as the format says, 1 y, 2 z
    int max_rules = 12;
    // Derive from the tree on screen as soon as one is shown and nothing grows
    // (`sylva-studio --infer tree`).
    bool from_tree_pending = false;
    std::future<InferOutcome> job;
    std::shared_ptr<std::atomic<bool>> cancel;
    std::optional<InferOutcome> result;
    std::string error;
    InferOverlay overlay = InferOverlay::Beside;
    glm::vec3 offset{0.0f};           // where the example's lines stand beside the regrown tree
    glm::vec3 low{0.0f}, high{0.0f};  // the example's bounds, unshifted
    float covered = 0.0f;  // the share of the 3D view's height the window covers, at its top
    std::unique_ptr<LineRenderer> lines;
    bool upload_pending = false;
    FileDialogState dialog;
};

// Starts a derivation (cancelling a running one): from the skeleton on screen with the
// parameters it was made with, or from a file read through core/input_file.h.
void start_infer_from_tree(InferPanel& panel, const StudioState& state);
void start_infer_from_file(InferPanel& panel, const std::string& path);

// True while a derivation runs or waits for the tree on screen.
bool infer_running(const InferPanel& panel);

// True for a file the panel reads rather than the template dialog (.json, .csv, .obj):
// what a file dropped on the window goes to.
bool is_skeleton_file(const std::string& path);

// Once per frame, with the GL context current: starts a pending derivation, takes a
// finished one (its template goes into the editor) and uploads the example's lines.
void update_infer_panel(InferPanel& panel, StudioState& state);

// The window, at the top of the 3D view, and its file dialog (call with the other
// dialogs, after every window: see panels.h's draw_dialogs).
void draw_infer_panel(InferPanel& panel, StudioState& state, const PanelLayout& layout);
void draw_infer_dialog(InferPanel& panel);

// The example's lines where the overlay puts them (nothing when off or before a result).
void draw_infer_overlay(const InferPanel& panel, const glm::mat4& view,
                        const glm::mat4& projection);

// The corners of the example's lines as shown, so "frame tree" takes them in, and a point
// above them that keeps both trees under the window.
std::vector<glm::vec3> infer_overlay_points(const InferPanel& panel);

// Cancels the job and waits for it (before the GL context goes away).
void release_infer_panel(InferPanel& panel);

}  // namespace sylva::studio
