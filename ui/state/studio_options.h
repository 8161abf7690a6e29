// sylva-studio's command line: an interactive window by default, or a scripted screenshot.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

namespace sylva::studio {

struct StudioOptions {
    bool help = false;
    std::optional<std::string> screenshot_path;  // render, save a PNG, exit
    int screenshot_frames = 5;                   // frames drawn before the capture
    std::string tree_template = "default";       // a built-in name or a template file
    bool low_poly = false;                       // start with the low-poly preview on
    int lod_level = 0;                           // ... showing this LOD level (--lod sets both)
    // Space colonization's overlays (ViewToggles): the envelope wire, the attraction points,
    // and growth replayed up to a step (clamped to the tree's last).
    bool envelope = true;
    bool points = false;
    std::optional<int> replay_iteration;
    // The Variants strip opened with this many seeds of the template (0: closed).
    int variants = 0;
    bool forest_preview = false;  // start with the forest view on (ui/forest_preview.h)
    std::optional<std::string> layout_example;  // open the layout panel on this example
    // Derive rules (ui/infer_panel.h) from "tree", the tree on screen, or a skeleton file.
    std::optional<std::string> infer_source;
    // Start with the wind on, frozen at this many seconds (for screenshots); unset: off.
    std::optional<float> wind_seconds;
    // A scripted slider drag (ui/state/release_bench.h): "KEY=VALUE", with the low-poly view on;
    // prints the time from release to the game mesh on screen and exits.
    std::optional<std::string> bench_release;
    double bench_hold_ms = 0;  // held still at the value this long before release
    // Open the template picker's grid (a screenshot waits until every thumbnail is drawn).
    bool template_picker = false;
    // The typing latency bench (ui/state/typing_bench.h): a growth job always running, the
    // rules editor focused; prints the editor's place, then the figures once this many
    // typed characters are on screen, and exits. 0: off.
    int bench_typing = 0;
    // ... without the growth job (the same figures with nothing growing, to compare).
    bool bench_no_job = false;
};

// A malformed command line; main prints the message and the usage, and exits with 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws UsageError for an unknown option, a missing or malformed value, --lod outside 0-3,
// --replay below 0, or --frames without --screenshot.
StudioOptions parse_studio_options(int argc, const char* const* argv);

std::string studio_usage();

}  // namespace sylva::studio
