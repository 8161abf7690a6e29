// What the studio's main loop does between frames, for tests without a loop: poll the jobs
// until no generation runs and none is stale, or the time runs out.
#pragma once

#include <chrono>
#include <thread>

#include "ui/state/studio_state.h"

namespace sylva::studio {

// True when the generations finished within `limit`.
inline bool wait_for_generations(StudioState& state,
                                 std::chrono::seconds limit = std::chrono::seconds(60)) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
        poll_jobs(state);
        if (!generation_running(state) && state.stale.empty()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

}  // namespace sylva::studio
