#include "ui/studio_state.h"

#include <exception>

namespace sylva::studio {

void start_generation(StudioState& state) {
    if (state.pending.valid()) state.pending.wait();
    state.error.clear();
    state.pending_since = std::chrono::steady_clock::now();
    // The worker gets copies, so editing the template while it runs is safe.
    state.pending = std::async(std::launch::async, [tree_template = state.tree_template] {
        return generate_tree(tree_template);
    });
}

bool generation_running(const StudioState& state) {
    return state.pending.valid();
}

bool collect_generation(StudioState& state) {
    if (!state.pending.valid() ||
        state.pending.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
        return false;
    }
    std::chrono::duration<double, std::milli> wall =
        std::chrono::steady_clock::now() - state.pending_since;
    state.last_wall_ms = wall.count();
    try {
        state.tree = state.pending.get();
        return true;
    } catch (const std::exception& e) {
        // The GUI's error boundary: bad input becomes a message, not a crash.
        state.error = e.what();
        return false;
    }
}

}  // namespace sylva::studio
