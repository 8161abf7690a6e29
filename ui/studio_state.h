// Everything the studio shows and the panels edit. The window, GL objects and ImGui live in
// main; this is plain data plus the tree being generated, so panels are functions of it.
#pragma once

#include <chrono>
#include <future>
#include <optional>
#include <string>

#include "app/pipeline.h"
#include "ui/orbit_camera.h"

namespace sylva::studio {

struct StudioState {
    TreeTemplate tree_template;
    std::optional<Tree> tree;   // the tree on screen, once one has been generated
    std::future<Tree> pending;  // the tree being generated, off the UI thread
    std::chrono::steady_clock::time_point pending_since;
    double last_wall_ms = 0;  // start-to-finish time of the last generation as the UI saw it
    std::string error;        // the last generation's error, shown in the panel
    OrbitCamera camera;
    bool quit_requested = false;
};

// Starts generating state.tree_template on a worker thread. A generation already running is
// waited for first (the pipeline has no cancel flag yet).
void start_generation(StudioState& state);

bool generation_running(const StudioState& state);

// Takes a finished generation, if any: moves its tree into state.tree, or its exception's
// message into state.error. Returns true when state.tree was replaced. Never blocks.
bool collect_generation(StudioState& state);

}  // namespace sylva::studio
