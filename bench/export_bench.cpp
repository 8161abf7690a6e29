// The game mesh, end to end: for every built-in template and budgets 200, 800
// and 3000, the whole `sylva export -o tree.glb` path (derive, turtle, fields, meshing,
// leaves, reduction, LOD-free finish, glb written) timed, side by side with meshoptimizer's
// meshopt_simplify called alone on the same raw trunk and crown (each part to its share of
// the budget by triangle count), and whether meshopt's parts stay closed 2-manifolds
// (check_topology). Speed goals live here, not in unit tests. One untimed export of the
// first template comes first: it starts the thread pool and faults in the heap, which the
// first timed template would otherwise pay alone; `sylva export`'s fresh process pays them
// once per tree. Each export is then made
// kRuns times in a row (the first of a tree larger than any before still grows the heap)
// and the fastest counts.
//
// Columns: raw = trunk + crown triangles as meshed; export ms = whole export, wall, the
// fastest of kRuns; first = the first of them; 1 core = the same export again on one
// thread (tbb::global_control), the work it does; cores = 1 core / export, what the second
// core bought (2 at best); reduce ms = its finish_tree share; meshopt ms = meshopt_simplify
// on both parts (the fastest of kRuns as well); ratio = export / meshopt; closed = Sylva's /
// meshopt's parts closed; mesh ms = the export's first stage alone, derive to the raw trunk
// and crown meshes meshopt_simplify is given (generate_tree; the leaves are made beside the
// meshing), and alone = mesh ms / meshopt ms. Under each budget, besides the medians against
// the targets: the first exports' median and worst; half the one-core times, what the
// exports would take with both cores busy all the way (the part of a target better use of
// the second core can reach; below that only less work helps); and the raw mesh alone
// against meshopt's call on it: where it is near 1 or above, no reduction, however fast,
// brings the whole export under meshopt's call. full raw = the tree meshed at its template's
// resolutions without a budget (as the studio shows it without "low poly"; the mesh a user
// would hand meshoptimizer), and vs full = export / meshopt_simplify on that mesh to the
// same budget (the fastest of kRuns too).
//
// With --stages, a line under each row says where the export's time went: the pipeline's
// stages (derive, growth, fields, trunk mesh, crown mesh, leaves), the reduction and the
// writing.
//
// Usage: sylva-bench-export [--stages] [TEMPLATE...]
#include <meshoptimizer.h>
#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "bench/common.h"
#include "core/mesh_checks.h"
#include "core/stopwatch.h"
#include "export/export_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace {

using namespace sylva;

bool closed(const Mesh& m) {
    return m.triangles.empty() || check_topology(m).is_closed_manifold();
}

// meshopt_simplify of one part to `target` triangles; the result keeps the part's
// positions (unused ones are harmless for check_topology's edge tests).
Mesh meshopt_reduce(const Mesh& m, std::size_t target) {
    Mesh out;
    if (m.triangles.empty()) return out;
    if (target >= m.triangles.size()) return m;  // nothing to reduce (a prism trunk's share)
    std::vector<unsigned> indices;
    indices.reserve(3 * m.triangles.size());
    for (const auto& t : m.triangles) indices.insert(indices.end(), t.begin(), t.end());
    std::vector<unsigned> reduced(indices.size());
    const std::size_t n =
        meshopt_simplify(reduced.data(), indices.data(), indices.size(), &m.positions[0].x,
                         m.positions.size(), sizeof(glm::vec3), 3 * target, 1.0f, 0, nullptr);
    out.positions = m.positions;
    for (std::size_t i = 0; i + 2 < n; i += 3)
        out.triangles.push_back({reduced[i], reduced[i + 1], reduced[i + 2]});
    return out;
}

// Each export (and meshopt's simplify) is timed this many times in a row; the fastest counts.
constexpr int kRuns = 3;

// meshopt_simplify on a tree's trunk and crown, `budget` triangles shared by their sizes:
// the fastest of kRuns, its parts left in trunk and crown.
double fastest_meshopt(const Tree& tree, std::size_t budget, Mesh& trunk, Mesh& crown) {
    const std::size_t raw = tree.trunk.triangles.size() + tree.crown.triangles.size();
    const std::size_t trunk_share = budget * tree.trunk.triangles.size() / raw;
    double fastest = 0.0;
    for (int run = 0; run < kRuns; ++run) {
        Stopwatch peer;
        trunk = meshopt_reduce(tree.trunk, trunk_share);
        crown = meshopt_reduce(tree.crown, budget - trunk_share);
        const double ms = peer.lap_ms();
        if (run == 0 || ms < fastest) fastest = ms;
    }
    return fastest;
}

}  // namespace

int main(int argc, char** argv) {
    // Its exports, like the studio's, follow each other in one process.
    bench::use_studio_heap();
    std::vector<std::string> names(argv + 1, argv + argc);
    const bool stages = std::erase(names, "--stages") > 0;
    if (names.empty())
        for (const TreeTemplate* t : builtin_templates()) names.push_back(t->name);
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "sylva_bench.glb";
    {
        const TreeTemplate warm_up = load_template(names.front());
        FinishSettings finish;
        finish.budget.total = kDefaultTriangleBudget;
        MeshOptions options;
        options.budget = game_budget(finish);
        const Tree tree = generate_tree(warm_up, options);
        write_tree(out, tree, finish_tree(tree, finish), warm_up.colors);
    }
    std::map<std::string, Tree> full_detail;
    for (const std::string& name : names) full_detail[name] = generate_tree(load_template(name));

    for (std::size_t budget : {200, 800, 3000}) {
        std::printf("budget %zu (trunk + crown; leaves thinned to the same number)\n", budget);
        std::printf("%-9s %7s %9s %7s %7s %5s %9s %10s %7s %7s %7s %5s %8s %8s\n", "template",
                    "raw", "export ms", "first", "1 core", "cores", "reduce ms", "meshopt ms",
                    "ratio", "closed", "mesh ms", "alone", "full raw", "vs full");
        std::vector<double> exports, firsts, ratios, halves, alone, against_full;
        std::size_t fewest_full = SIZE_MAX, most_full = 0;
        for (const std::string& name : names) {
            const TreeTemplate tmpl = load_template(name);
            FinishSettings finish;
            finish.budget.total = budget;
            MeshOptions options;
            options.budget = game_budget(finish);

            // The export kRuns times in a row, the fastest counting: the first of a tree larger
            // than any before grows the heap (a first touch of a page costs microseconds
            // here), as it does once in the studio; the others are what each export after it
            // takes. The first is shown beside it.
            double export_ms = 0.0, first_ms = 0.0, mesh_ms = 0.0, reduce_ms = 0.0, write_ms = 0.0;
            Tree tree;
            FinishedTree finished;
            for (int run = 0; run < kRuns; ++run) {
                Stopwatch whole;
                Tree made = generate_tree(tmpl, options);
                const double made_mesh_ms = whole.lap_ms();
                Stopwatch reduce;
                FinishedTree done = finish_tree(made, finish);
                const double made_reduce_ms = reduce.lap_ms();
                write_tree(out, made, done, tmpl.colors);
                const double made_write_ms = reduce.lap_ms();
                const double ms = made_mesh_ms + whole.lap_ms();
                if (run == 0) first_ms = ms;
                if (run == 0 || ms < export_ms) {
                    export_ms = ms;
                    mesh_ms = made_mesh_ms;
                    reduce_ms = made_reduce_ms;
                    write_ms = made_write_ms;
                    tree = std::move(made);
                    finished = std::move(done);
                }
            }

            const std::size_t raw = tree.trunk.triangles.size() + tree.crown.triangles.size();
            Mesh trunk, crown, unused_trunk, unused_crown;
            const double meshopt_ms = fastest_meshopt(tree, budget, trunk, crown);
            const Tree& full = full_detail.at(name);
            const std::size_t full_raw = full.trunk.triangles.size() + full.crown.triangles.size();
            const double full_ms = fastest_meshopt(full, budget, unused_trunk, unused_crown);

            double one_core_ms = 0.0;
            {
                const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism,
                                                     1);
                Stopwatch one_core;
                const Tree again = generate_tree(tmpl, options);
                write_tree(out, again, finish_tree(again, finish), tmpl.colors);
                one_core_ms = one_core.lap_ms();
            }

            const ReducedTree& r = finished.levels.at(0);
            const bool ours = closed(r.trunk) && closed(r.crown);
            const bool theirs = closed(trunk) && closed(crown);
            std::printf(
                "%-9s %7zu %9.1f %7.1f %7.1f %5.2f %9.1f %10.1f %6.1fx %3s/%-3s %7.1f %4.1fx %8zu "
                "%7.1fx\n",
                name.c_str(), raw, export_ms, first_ms, one_core_ms, one_core_ms / export_ms,
                reduce_ms, meshopt_ms, export_ms / meshopt_ms, ours ? "yes" : "NO",
                theirs ? "yes" : "no", mesh_ms, mesh_ms / meshopt_ms, full_raw,
                export_ms / full_ms);
            if (stages) {
                std::printf("%9s", "");
                for (const StageTime& stage : tree.times)
                    std::printf(" %s %.1f,", stage.name.c_str(), stage.ms);
                std::printf(" reduce %.1f, write %.1f ms\n", reduce_ms, write_ms);
            }
            std::fflush(stdout);
            exports.push_back(export_ms);
            firsts.push_back(first_ms);
            ratios.push_back(export_ms / meshopt_ms);
            halves.push_back(0.5 * one_core_ms);
            alone.push_back(mesh_ms / meshopt_ms);
            against_full.push_back(export_ms / full_ms);
            fewest_full = std::min(fewest_full, full_raw);
            most_full = std::max(most_full, full_raw);
        }
        std::printf(
            "export: median %.1f ms, worst %.1f ms (targets 25 / 50 ms); "
            "export / meshopt_simplify alone: median %.1fx (target <= 1)\n"
            "the first of each tree: median %.1f ms, worst %.1f ms\n"
            "both cores busy all the way (half of one core's): median %.1f ms, worst %.1f ms\n"
            "the raw mesh alone / meshopt_simplify on it: median %.2fx, %.2f-%.2fx\n"
            "export / meshopt_simplify on the full-detail mesh (%zu-%zu triangles): median %.2fx, "
            "%.2f-%.2fx\n\n",
            bench::median(exports), *std::max_element(exports.begin(), exports.end()),
            bench::median(ratios), bench::median(firsts),
            *std::max_element(firsts.begin(), firsts.end()), bench::median(halves),
            *std::max_element(halves.begin(), halves.end()), bench::median(alone),
            *std::min_element(alone.begin(), alone.end()),
            *std::max_element(alone.begin(), alone.end()), fewest_full, most_full,
            bench::median(against_full),
            *std::min_element(against_full.begin(), against_full.end()),
            *std::max_element(against_full.begin(), against_full.end()));
    }
    std::filesystem::remove(out);
    return 0;
}
