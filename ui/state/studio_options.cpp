#include "ui/state/studio_options.h"

#include <charconv>
#include <string_view>

#include "ui/state/studio_state.h"

namespace sylva::studio {

StudioOptions parse_studio_options(int argc, const char* const* argv) {
    StudioOptions options;
    bool frames_given = false;
    for (int i = 1; i < argc; ++i) {
        std::string_view arg = argv[i];
        auto value = [&]() -> std::string_view {
            if (i + 1 >= argc) throw UsageError(std::string(arg) + " needs a value");
            return argv[++i];
        };
        if (arg == "-h" || arg == "--help") {
            options.help = true;
        } else if (arg == "--screenshot") {
            std::string_view path = value();
            if (path.empty()) throw UsageError("--screenshot needs a file name");
            options.screenshot_path = std::string(path);
        } else if (arg == "--template" || arg == "-t") {
            std::string_view name = value();
            if (name.empty()) throw UsageError("--template needs a name or a file");
            options.tree_template = std::string(name);
        } else if (arg == "--low-poly") {
            options.low_poly = true;
        } else if (arg == "--lod") {
            std::string_view text = value();
            int level = -1;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), level);
            if (error != std::errc() || end != text.data() + text.size() || level < 0 || level > 3)
                throw UsageError("--lod takes a level from 0 to 3, got '" + std::string(text) +
                                 "'");
            options.lod_level = level;
            options.low_poly = true;
        } else if (arg == "--impostor") {  // the LOD slider's slot after LOD 3
            options.lod_level = kLodLevels;
            options.low_poly = true;
        } else if (arg == "--no-envelope") {
            options.envelope = false;
        } else if (arg == "--points") {
            options.points = true;
        } else if (arg == "--replay") {
            std::string_view text = value();
            int step = -1;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), step);
            if (error != std::errc() || end != text.data() + text.size() || step < 0)
                throw UsageError("--replay takes a growth step of at least 0, got '" +
                                 std::string(text) + "'");
            options.replay_iteration = step;
        } else if (arg == "--variants") {
            std::string_view text = value();
            int count = 0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
            if (error != std::errc() || end != text.data() + text.size() || count < 1 || count > 12)
                throw UsageError("--variants takes a count from 1 to 12, got '" +
                                 std::string(text) + "'");
            options.variants = count;
        } else if (arg == "--forest-preview") {
            options.forest_preview = true;
        } else if (arg == "--layout") {
            const std::string_view name = value();
            if (name.empty()) throw UsageError("--layout needs an example name");
            options.layout_example = std::string(name);
        } else if (arg == "--infer") {
            const std::string_view source = value();
            if (source.empty()) throw UsageError("--infer needs 'tree' or a skeleton file");
            options.infer_source = std::string(source);
        } else if (arg == "--wind") {
            std::string_view text = value();
            float seconds = -1.0f;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seconds);
            if (error != std::errc() || end != text.data() + text.size() || !(seconds >= 0.0f))
                throw UsageError("--wind takes a time in seconds of at least 0, got '" +
                                 std::string(text) + "'");
            options.wind_seconds = seconds;
        } else if (arg == "--bench-release") {
            const std::string_view text = value();
            if (text.find('=') == std::string_view::npos)
                throw UsageError("--bench-release takes KEY=VALUE, got '" + std::string(text) +
                                 "'");
            options.bench_release = std::string(text);
            options.low_poly = true;
        } else if (arg == "--bench-hold") {
            std::string_view text = value();
            double ms = -1.0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), ms);
            if (error != std::errc() || end != text.data() + text.size() || !(ms >= 0.0))
                throw UsageError("--bench-hold takes milliseconds of at least 0, got '" +
                                 std::string(text) + "'");
            options.bench_hold_ms = ms;
        } else if (arg == "--bench-no-job") {
            options.bench_no_job = true;
        } else if (arg == "--template-picker") {
            options.template_picker = true;
        } else if (arg == "--bench-typing") {
            std::string_view text = value();
            int keys = 0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), keys);
            if (error != std::errc() || end != text.data() + text.size() || keys < 1)
                throw UsageError("--bench-typing takes a count of keys of at least 1, got '" +
                                 std::string(text) + "'");
            options.bench_typing = keys;
        } else if (arg == "--frames") {
            std::string_view text = value();
            int frames = 0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), frames);
            if (error != std::errc() || end != text.data() + text.size() || frames < 1) {
                throw UsageError("--frames takes a whole number of at least 1, got '" +
                                 std::string(text) + "'");
            }
            options.screenshot_frames = frames;
            frames_given = true;
        } else {
            throw UsageError("unknown option '" + std::string(arg) + "'");
        }
    }
    if (frames_given && !options.screenshot_path) {
        throw UsageError("--frames only applies with --screenshot");
    }
    return options;
}

std::string studio_usage() {
    return "usage: sylva-studio [--template NAME|FILE] [--low-poly] [--lod N] [--impostor]\n"
           "                    [--no-envelope] [--points]\n"
           "                    [--replay STEP] [--variants N] [--layout EXAMPLE] [--wind "
           "SECONDS]\n"
           "                    [--forest-preview] [--infer tree|SKELETON]\n"
           "                    [--screenshot PATH [--frames N]]\n"
           "                    [--bench-release KEY=VALUE [--bench-hold MS]]\n"
           "                    [--template-picker] [--bench-typing KEYS [--bench-no-job]]\n"
           "\n"
           "Opens the Sylva tree modeler window (OpenGL 3.3) with the built-in default tree.\n"
           "\n"
           "  -t, --template T   start with a built-in template or a template/grammar file\n"
           "  --low-poly         show the game mesh: what an export at the template's budget\n"
           "                     writes (trunk + crown reduced, leaves thinned)\n"
           "  --lod N            show level N (0-3) of its LOD chain; implies --low-poly\n"
           "  --impostor         show the octahedral impostor (export --impostor) instead\n"
           "  --no-envelope      space colonization: hide the envelope's wire cage\n"
           "  --points           space colonization: show the attraction points\n"
           "  --replay STEP      space colonization: show the skeleton as growth left it after\n"
           "                     STEP (0: the trunk), without the meshes\n"
           "  --variants N       open the Variants strip with N (1-12) seeds of the template\n"
           "  --forest-preview   start with the forest view on: a 40 x 40 m square planted with\n"
           "                     the template (sylva forest's spacing, 4 variants)\n"
           "  --layout EXAMPLE   open the 2D layout panel on a shipped example (sylva layout\n"
           "                     examples lists them) or a .mesh / .json file; with\n"
           "                     --forest-preview its first variation is planted\n"
           "  --infer tree|SKELETON\n"
           "                     derive rules from the tree on screen or a skeleton file\n"
           "                     (skeleton.json, cylinder CSV, OBJ lines) and load them, with\n"
           "                     the example beside the regrown tree (docs/infer.md)\n"
           "  --wind SECONDS     wind on, frozen at that time (for screenshots of the sway)\n"
           "  --screenshot PATH  draw N frames, save the window as a PNG at PATH, and exit\n"
           "  --frames N         frames to draw before the screenshot (default 5)\n"
           "  --bench-release KEY=VALUE\n"
           "                     low-poly view on; once the game mesh shows, drag KEY's slider\n"
           "                     to VALUE over 8 frames, let go, print the time from release\n"
           "                     to the new game mesh on screen, and exit (with --screenshot:\n"
           "                     saving that frame)\n"
           "  --bench-hold MS    hold the slider still at VALUE this long before letting go\n"
           "  --template-picker  open the template picker's thumbnails (with --screenshot:\n"
           "                     once every thumbnail is drawn)\n"
           "  --bench-typing KEYS\n"
           "                     keep a growth job running, focus the rules editor, print\n"
           "                     'typing bench: ready X Y W H' (the editor's place), and once\n"
           "                     KEYS typed characters are on screen print the time from each\n"
           "                     key to its frame and exit (bench/typing_latency_bench.cpp\n"
           "                     types them)\n"
           "  --bench-no-job     the typing bench without the growth job, to compare\n"
           "  -h, --help         show this help\n"
           "\n"
           "Without a display, use the command-line tool instead: sylva export -o tree.obj\n";
}

}  // namespace sylva::studio
