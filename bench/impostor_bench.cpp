// Impostor baking (impostor/): for each template given (default oak, spruce, palm, willow),
// the game tree as an export finishes it (800 + 800 leaf triangles), then the best of
// `--repeat` runs (default 5) of
//   atlas     bake_impostor: 8 x 8 views at 1024 px, 2 x 2 samples a pixel, with depth
//   billboard bake_billboard: 3 side views of 256 px
//   png       encode_png of the atlas's two images (what an export adds on top)
// as wall time on the TBB pool (both cores) and CPU time of all threads (the steadier
// figure on a busy machine: wall = cpu / 2 on two idle cores). An
// export without --impostor calls none of this (its bytes are the golden ones).
// `--size auto` bakes the layout chosen per tree (impostor/impostor_layout.h: "layout" is the
// one chosen, "thin %" the thin share that chose it; the bake time includes both bakes).
// With --fidelity, also the worst silhouette IoU from the capture directions and from the 8
// between them, and the worst colour difference (impostor/impostor_fidelity.h); `all` for
// every built-in template.
//
// Usage: sylva-bench-impostor [--markdown] [--repeat N] [--size PX|auto] [--views N] [--fidelity]
//                             [all | TEMPLATE...]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/common.h"
#include "core/color_variation.h"
#include "export/export_tree.h"
#include "impostor/impostor_fidelity.h"
#include "impostor/impostor_files.h"
#include "impostor/impostor_layout.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

using namespace sylva;

int main(int argc, char** argv) {
    int repeat = 5;
    ImpostorSettings settings;
    std::vector<std::string> names;
    bool markdown = false;
    bool fidelity = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (arg == "--size" && i + 1 < argc) {
            const std::string v = argv[++i];
            settings.size = v == "auto" ? 0 : std::atoi(v.c_str());
        } else if (arg == "--views" && i + 1 < argc)
            settings.views = std::atoi(argv[++i]);
        else if (arg == "--markdown")
            markdown = true;
        else if (arg == "--fidelity")
            fidelity = true;
        else if (arg == "all")
            for (const TreeTemplate* t : builtin_templates()) names.push_back(t->name);
        else
            names.push_back(arg);
    }
    if (names.empty()) names = {"oak", "spruce", "palm", "willow"};
    const bool automatic = settings.size == 0;
    if (!automatic) settings = clamped(settings);

    if (automatic)
        std::printf("impostor bake, layout chosen per tree (impostor_layout.h), best of %d\n",
                    repeat);
    else
        std::printf("impostor bake, %d x %d views at %d px (tiles of %d), best of %d\n",
                    settings.views, settings.views, settings.size, settings.size / settings.views,
                    repeat);
    std::vector<std::string> header{"template",   "triangles",    "thin %",       "layout",
                                    "atlas ms",   "atlas cpu ms", "billboard ms", "png ms",
                                    "png cpu ms", "png KiB"};
    if (fidelity) header.insert(header.end(), {"IoU capture", "IoU between", "colour/255"});
    bench::Table table(header);
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
        const bench::Times bake =
            bench::best_of(repeat, [&] { atlas = bake_impostor(parts, settings); });
        const double thin = atlas.thin >= 0.0 ? atlas.thin : thin_share(atlas);
        const bench::Times billboard =
            bench::best_of(repeat, [&] { (void)bake_billboard(parts, settings); });
        std::size_t png_bytes = 0;
        const bench::Times png = bench::best_of(repeat, [&] {
            png_bytes = encode_png(atlas.albedo).size() + encode_png(atlas.normal).size();
        });
        worst = std::max(worst, bake.wall_ms);
        worst_cpu = std::max(worst_cpu, bake.cpu_ms);
        std::vector<std::string> cells{
            name,
            std::to_string(triangles),
            bench::format("%.1f", thin * 100.0),
            bench::format("%dx%d@%d", atlas.views, atlas.views, atlas.tile * atlas.views),
            bench::format("%.1f", bake.wall_ms),
            bench::format("%.1f", bake.cpu_ms),
            bench::format("%.1f", billboard.wall_ms),
            bench::format("%.1f", png.wall_ms),
            bench::format("%.1f", png.cpu_ms),
            bench::format("%.0f", static_cast<double>(png_bytes) / 1024.0)};
        if (fidelity) {
            const ImpostorFidelity f = impostor_fidelity(parts, atlas);
            cells.insert(cells.end(),
                         {bench::format("%.3f", f.capture_iou),
                          bench::format("%.4f", f.between_iou), bench::format("%.2f", f.color)});
        }
        table.row(std::move(cells));
    }
    table.print(markdown);
    // CPU time bounds the wall time of an idle machine from above (both threads' work,
    // as if done one after the other); on a busy machine the wall time is the scheduler's.
    std::printf(
        "slowest atlas bake: %.1f ms wall, %.1f ms CPU of both threads (goal: at most 100 ms on "
        "2 cores)\n",
        worst, worst_cpu);
    return 0;
}
