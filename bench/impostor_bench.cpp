// Impostor baking (impostor/): for each template given (default oak, spruce, palm, willow),
// the game tree as an export finishes it (800 + 800 leaf triangles), then the best of
// `--repeat` runs (default 5) of
//   atlas     bake_impostor: 8 x 8 views at 1024 px, 2 x 2 samples a pixel, with depth
//   billboard bake_billboard: 3 side views of 256 px
//   png       encode_png of the atlas's two images (what an export adds on top)
// as wall time on the TBB pool (both cores) and CPU time of all threads (the steadier
// figure on a busy machine: wall = cpu / 2 on two idle cores). An
// export without --impostor calls none of this (its bytes are the golden ones).
// With --fidelity, also the worst silhouette IoU from the capture directions and from the 8
// between them, and the worst colour difference (impostor/impostor_fidelity.h); `all` for
// every built-in template.
//
// Usage: sylva-bench-impostor [--repeat N] [--size PX] [--views N] [--fidelity]
//                             [all | TEMPLATE...]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <limits>
#include <string>
#include <vector>

#include "core/color_variation.h"
#include "core/stopwatch.h"
#include "export/export_tree.h"
#include "impostor/impostor_fidelity.h"
#include "impostor/impostor_files.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace {

using namespace sylva;

double process_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

// Best wall time and best CPU time (all threads) of `repeat` runs.
struct Times {
    double wall = std::numeric_limits<double>::max();
    double cpu = std::numeric_limits<double>::max();
};

template <class F>
Times best_ms(int repeat, F&& f) {
    Times best;
    for (int r = 0; r < repeat; ++r) {
        Stopwatch clock;
        const double cpu = process_cpu_ms();
        f();
        best.wall = std::min(best.wall, clock.lap_ms());
        best.cpu = std::min(best.cpu, process_cpu_ms() - cpu);
    }
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    int repeat = 5;
    ImpostorSettings settings;
    std::vector<std::string> names;
    bool fidelity = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (arg == "--size" && i + 1 < argc)
            settings.size = std::atoi(argv[++i]);
        else if (arg == "--views" && i + 1 < argc)
            settings.views = std::atoi(argv[++i]);
        else if (arg == "--fidelity")
            fidelity = true;
        else if (arg == "all")
            for (const TreeTemplate* t : builtin_templates()) names.push_back(t->name);
        else
            names.push_back(arg);
    }
    if (names.empty()) names = {"oak", "spruce", "palm", "willow"};
    settings = clamped(settings);

    std::printf("impostor bake, %d x %d views at %d px (tiles of %d), best of %d, wall ms\n",
                settings.views, settings.views, settings.size, settings.size / settings.views,
                repeat);
    std::printf("%-15s %9s %8s %8s %10s %10s %8s %9s%s\n", "template", "triangles", "atlas",
                "atlas cpu", "billboard", "png", "png cpu", "png KiB",
                fidelity ? "  IoU capture  between  colour/255" : "");
    double worst = 0.0, worst_cpu = 0.0;
    for (const std::string& name : names) {
        TreeTemplate t = load_template(name);
        t.colors = tree_colors(t);
        FinishSettings finish;
        finish.budget.total = static_cast<std::size_t>(t.params.triangle_budget);
        MeshOptions mesh;
        mesh.budget = game_budget(finish);
        const Tree tree = generate_tree(t, mesh);
        const FinishedTree finished = finish_tree(tree, finish);
        const EngineModel model = engine_model(tree, finished, t.colors, ExportOptions{});
        const std::vector<BakePart> parts = bake_parts(model.levels[0]);
        std::size_t triangles = 0;
        for (const BakePart& p : parts) triangles += p.mesh->triangles.size();

        ImpostorAtlas atlas;
        const Times bake = best_ms(repeat, [&] { atlas = bake_impostor(parts, settings); });
        const Times billboard = best_ms(repeat, [&] { (void)bake_billboard(parts, settings); });
        std::size_t png_bytes = 0;
        const Times png = best_ms(repeat, [&] {
            png_bytes = encode_png(atlas.albedo).size() + encode_png(atlas.normal).size();
        });
        worst = std::max(worst, bake.wall);
        worst_cpu = std::max(worst_cpu, bake.cpu);
        std::printf("%-15s %9zu %8.1f %8.1f %10.1f %10.1f %8.1f %9.0f", name.c_str(), triangles,
                    bake.wall, bake.cpu, billboard.wall, png.wall, png.cpu,
                    static_cast<double>(png_bytes) / 1024.0);
        if (fidelity) {
            const ImpostorFidelity f = impostor_fidelity(parts, atlas);
            std::printf("        %.3f    %.3f  %6.2f", f.capture_iou, f.between_iou, f.color);
        }
        std::printf("\n");
    }
    // CPU time bounds the wall time of an idle machine from above (both threads' work,
    // as if done one after the other); on a busy machine the wall time is the scheduler's.
    std::printf(
        "slowest atlas bake: %.1f ms wall, %.1f ms CPU of both threads (goal: at most 100 ms on "
        "2 cores)\n",
        worst, worst_cpu);
    return 0;
}
