// A scripted slider drag for measuring what the artist waits for: the time from letting go of
// a slider to the new game mesh on screen, in the studio's own clock (--bench-release). No
// GL here: main drives it once per frame and says when the frame is on screen.
#pragma once

#include <chrono>
#include <string>
#include <string_view>

#include "ui/state/studio_state.h"

namespace sylva::studio {

struct ReleaseBench {
    std::string key;      // the parameter the "slider" moves
    double target = 0.0;  // where the drag ends
    int steps = 8;        // frames the drag takes, one value per frame
    double hold_ms = 0;   // the slider held still at the target before it is let go
    enum Phase { WaitForTree, Drag, Hold, Released, Done };
    Phase phase = WaitForTree;
    double start_value = 0.0;
    int step = 0;
    std::chrono::steady_clock::time_point hold_until, released;
    double release_ms = 0;  // the measurement, once Done
    int frames = 0;         // frames drawn from release to done
};

// "KEY=VALUE": a parameter of tree/params and the value the drag ends at. Throws
// std::invalid_argument naming what is wrong (unknown key, not a number).
ReleaseBench parse_release_bench(std::string_view text);

// One frame, before the main loop starts generations: moves the template's parameter one
// step towards the target while "dragging" and returns whether the slider is held (what
// main puts in state.dragging). Waits for the first game mesh before the drag starts.
bool drive_release_bench(ReleaseBench& bench, StudioState& state);

// True once the game mesh of the target value is what the view holds (call after the frame
// that uploaded it is drawn): the bench is then Done with release_ms measured.
bool release_bench_done(ReleaseBench& bench, const StudioState& state);

// "willow tropism 0.45 -> 0.6, 8 frames, held 0 ms: release -> game mesh on screen 812 ms
// (reduce 790 ms)".
std::string release_bench_report(const ReleaseBench& bench, const StudioState& state);

}  // namespace sylva::studio
