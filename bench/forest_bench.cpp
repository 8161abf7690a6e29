// A planted forest (the target: 1,000 trees of 5 species x 8 variants, budget 800
// each, written in <= 3 s on 2 cores; the unique variants dominate, instances cost
// nothing). Prints the time split: planning (Poisson disk, stands, variant choice), variant
// generation (oneTBB over the 40 variants), and writing the glb scene + placement lists.
//   build/bench/sylva-bench-forest [--markdown] [OUT_DIR]   (default: the system's temp folder)
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/common.h"
#include "core/stopwatch.h"
#include "forest/forest.h"
#include "tree/template_library.h"

using namespace sylva;

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    const bool markdown = bench::take_flag(args, "--markdown");
    const std::filesystem::path dir =
        args.empty() ? std::filesystem::temp_directory_path() : std::filesystem::path(args[0]);
    forest::ForestSettings s;
    for (const char* name : {"oak", "birch", "spruce", "pine", "palm"})
        s.species.push_back({load_template(name), 1.0});
    s.variants = 8;
    s.ground = forest::rectangle_ground(180.0, 180.0);
    s.spacing = 4.0;
    s.trees = 1000;
    s.finish.budget.total = 800;
    const std::filesystem::path glb = dir / "sylva-bench-forest.glb";

    Stopwatch clock;
    const forest::ForestResult r = forest::plant_forest(s, glb);
    const double total = clock.lap_ms();
    std::size_t triangles = 0, instanced = 0;
    for (std::size_t t : r.variant_triangles) triangles += t;
    for (const forest::Placement& p : r.plan.placements)
        instanced += r.variant_triangles[p.variant];
    bench::Table table({"trees", "species x variants", "budget", "unique triangles",
                        "instanced triangles", "plan ms", "variants ms", "write ms", "total ms",
                        "scene MB"});
    table.row({std::to_string(r.plan.placements.size()),
               std::to_string(s.species.size()) + " x " + std::to_string(s.variants),
               std::to_string(s.finish.budget.total), std::to_string(triangles),
               std::to_string(instanced), bench::format("%.1f", r.times.plan_ms),
               bench::format("%.1f", r.times.variants_ms), bench::format("%.1f", r.times.write_ms),
               bench::format("%.1f", total),
               bench::format("%.2f", static_cast<double>(std::filesystem::file_size(glb)) / 1e6)});
    table.print(markdown);
    if (!markdown) std::printf("target: total <= 3000 ms on two cores\n");
    for (const auto& file : r.files) std::filesystem::remove(file);
    return 0;
}
