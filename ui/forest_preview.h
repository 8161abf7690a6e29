// The "forest" view toggle: a small square of forest planted with the shown template
// (ui/state/forest_preview_plan.h), made on a worker at a low budget and drawn in place of the
// single tree once ready. The tree stays on screen meanwhile; a new template cancels a
// running job and starts another; turning it off returns to the tree.
#pragma once

#include <atomic>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "ui/mesh_renderer.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {

struct ForestPreview {
    std::future<ForestPreviewMeshes> job;
    std::shared_ptr<std::atomic<bool>> cancel;
    std::shared_ptr<std::atomic<int>> done, total;  // variants made, of how many
    TreeTemplate job_template;                      // what the job (or the shown forest) plants
    ForestPreviewOptions job_options;
    ForestPreviewPlan job_plan, shown_plan;  // the plan planted instead of the square, if any
    bool has_job = false;  // job_template / job_options hold a started job's input
    // Cancelled jobs until their workers notice: a std::async future blocks in its
    // destructor, so dropping one at once would freeze the UI until it stops.
    std::vector<std::future<ForestPreviewMeshes>> stale;
    std::unique_ptr<MeshRenderer> trunk, crown, leaves;  // created with the first forest
    bool ready = false;                                  // the renderers hold a forest
    TreeTemplate shown_template;                         // ... planted with this
    ForestPreviewOptions shown_options;
    std::size_t trees = 0, triangles = 0;
    glm::vec3 low{0.0f}, high{0.0f};
    bool was_on = false;
    bool frame_pending = false;  // frame the camera on the area when the forest arrives
    std::string error;
};

// The View section's row: the toggle, the area's size, K, and the progress or error.
void forest_preview_row(StudioState& state);

// Once per frame with the GL context current: starts a job when the toggle is on and the
// shown template or the options changed (cancelling a stale one), takes a finished forest
// and uploads it, updates state.forest_status. Returns true when the camera should be
// framed on the area now (a first forest, or the toggle just turned on with one ready).
bool update_forest_preview(ForestPreview& preview, StudioState& state);

// True when the viewport should draw the forest instead of the tree.
bool forest_preview_shown(const ForestPreview& preview, const StudioState& state);
bool forest_preview_running(const ForestPreview& preview);

// Corner points of the planted area and the forest's top, for frame_points().
std::vector<glm::vec3> forest_preview_frame_points(const ForestPreview& preview);

// Cancels the job and waits for it (before the GL context goes away).
void release_forest_preview(ForestPreview& preview);

}  // namespace sylva::studio
