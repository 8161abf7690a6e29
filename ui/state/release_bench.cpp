#include "ui/state/release_bench.h"

#include <charconv>
#include <cstdio>
#include <stdexcept>

#include "core/tree_params.h"
#include "tree/parameters.h"
#include "tree/pipeline.h"

namespace sylva::studio {
namespace {

using Clock = std::chrono::steady_clock;

bool game_mesh_shown(const StudioState& state) {
    return state.tree && state.tree->reduced() && !state.tree->draft && !state.tree_changed;
}

}  // namespace

ReleaseBench parse_release_bench(std::string_view text) {
    const std::size_t equals = text.find('=');
    if (equals == std::string_view::npos)
        throw std::invalid_argument("--bench-release takes KEY=VALUE, got '" + std::string(text) +
                                    "'");
    ReleaseBench bench;
    bench.key = std::string(text.substr(0, equals));
    if (!get_param(TreeParams{}, bench.key))
        throw std::invalid_argument("--bench-release: no parameter '" + bench.key + "'");
    const std::string_view value = text.substr(equals + 1);
    auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), bench.target);
    if (error != std::errc() || end != value.data() + value.size())
        throw std::invalid_argument("--bench-release: '" + std::string(value) +
                                    "' is not a number");
    return bench;
}

bool drive_release_bench(ReleaseBench& bench, StudioState& state) {
    switch (bench.phase) {
        case ReleaseBench::WaitForTree:
            if (game_mesh_shown(state) && !generation_running(state)) {
                bench.start_value = *get_param(state.tree_template.params, bench.key);
                bench.phase = ReleaseBench::Drag;
            }
            return false;
        case ReleaseBench::Drag: {
            ++bench.step;
            const double t = static_cast<double>(bench.step) / bench.steps;
            const double value = bench.step == bench.steps
                                     ? bench.target
                                     : bench.start_value + t * (bench.target - bench.start_value);
            set_param(state.tree_template.params, bench.key, value);
            if (bench.step == bench.steps) {
                bench.phase = ReleaseBench::Hold;
                bench.hold_until = Clock::now() + std::chrono::microseconds(
                                                      static_cast<long>(bench.hold_ms * 1e3));
            }
            return true;
        }
        case ReleaseBench::Hold:
            if (Clock::now() < bench.hold_until) return true;
            bench.phase = ReleaseBench::Released;
            bench.released = Clock::now();
            return false;
        case ReleaseBench::Released:
        case ReleaseBench::Done:
            return false;
    }
    return false;
}

bool release_bench_done(ReleaseBench& bench, const StudioState& state) {
    if (bench.phase == ReleaseBench::Done) return true;
    if (bench.phase == ReleaseBench::Released) ++bench.frames;
    // The game mesh of the value let go at, at the level viewed, is on screen (a job may
    // still be making the chain's coarser levels).
    if (bench.phase != ReleaseBench::Released || !game_mesh_shown(state) ||
        get_param(state.shown_template.params, bench.key) != bench.target ||
        static_cast<int>(state.tree->finished.levels.size()) <= state.view.lod_level)
        return false;
    bench.release_ms =
        std::chrono::duration<double, std::milli>(Clock::now() - bench.released).count();
    bench.phase = ReleaseBench::Done;
    return true;
}

std::string release_bench_report(const ReleaseBench& bench, const StudioState& state) {
    const double generation_ms = state.tree ? stages_wall_ms(state.tree->tree.times) : 0.0;
    char text[360];
    std::snprintf(text, sizeof text,
                  "%s %s %g -> %g, %d frames, held %.0f ms: release -> game mesh on screen "
                  "%.0f ms, %d frames drawn meanwhile (its job %.0f ms: growth and meshes %.0f "
                  "ms, reduction %.0f ms)",
                  state.shown_template.name.c_str(), bench.key.c_str(), bench.start_value,
                  bench.target, bench.steps, bench.hold_ms, bench.release_ms, bench.frames,
                  state.last_wall_ms, generation_ms, state.tree ? state.tree->reduce_ms : 0.0);
    return text;
}

}  // namespace sylva::studio
