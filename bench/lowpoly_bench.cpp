// Low poly for real: every built-in template at its "game" setting (its default
// resolutions, trunk + crown reduced to at most 800 triangles) against its resolution-200
// surface, and plain marching cubes at the resolution that reaches the same mean error.
// Then the time to reduce a ~100k-triangle tree.
//
// Columns: input = trunk + crown as meshed; tris = after reduction; cuts = handles cut to
// get there (lowpoly/handle_cutting.h); ms = the reduction's wall time; closed = both
// parts closed 2-manifolds;
// mean / max = one-sided distance from the reduced surface to the resolution-200 surface,
// in % of the tree's height (20,000 samples); haus = the symmetric Hausdorff distance (the
// larger max of both directions, so a dropped branch counts; target at 200: <= 15);
// the tree is meshed as the export meshes it for the budget; MC res / MC tris = the coarsest plain
// marching-cubes resolution (trunk and crown) whose mean error is at most the reduced
// tree's, and its triangles; ratio = MC tris / reduced tris (target >= 5).
//
// Usage: sylva-bench-lowpoly [--budget N] [--quick] [--where] [TEMPLATE...]
//   --quick  the reference at resolution 120 instead of 200 (a rough look in a minute)
//   --where  also where each direction's largest distance is, and the triangles each part
//            kept: to find what a budget loses
//   --fidelity-only  skip the marching-cubes match and the speed run (MC columns show 0)
//   --heap-only  collapses one at a time from the heap all the way (DecimateSettings::
//            fast_passes off: the reducer before passes), to compare in one run with
//   --compare-heap  a second line per template: the heap-only reduction's ms, mean, max and
//            Hausdorff distance beside the default's
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "core/mesh_checks.h"
#include "lowpoly/decimate.h"
#include "lowpoly/fidelity.h"
#include "lowpoly/merge_meshes.h"
#include "lowpoly/surface_sampling.h"
#include "lowpoly/triangle_bvh.h"
#include "tree/lowpoly_tree.h"
#include "tree/template_library.h"

namespace {

using namespace sylva;

bool closed(const Mesh& m) {
    return m.triangles.empty() || check_topology(m).is_closed_manifold();
}

// Plain marching cubes: the coarsest resolution in `resolutions` whose mean error is at
// most `target`; {0, 0, 0} when none is.
struct PlainMatch {
    int resolution = 0;
    std::size_t triangles = 0;
    double mean_percent = 0;
};

PlainMatch plain_match(const TreeTemplate& tmpl, const Mesh& reference, double target,
                       int max_resolution) {
    for (int r : {8, 12, 16, 20, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 160, 200}) {
        if (r > max_resolution) break;
        TreeTemplate t = tmpl;
        t.params.trunk_resolution = r;
        t.params.crown_resolution = r;
        const Tree tree = generate_tree(t);
        const Fidelity f = measure_tree_fidelity(tree.trunk, tree.crown, reference);
        if (f.mean_percent <= target)
            return {r, tree.trunk.triangles.size() + tree.crown.triangles.size(), f.mean_percent};
    }
    return {};
}

// The sample of `from` farthest from `to` (the same samples measure_fidelity takes), and
// its distance in % of `height`.
void print_farthest(const char* label, const Mesh& from, const Mesh& to, double height) {
    const TriangleBvh bvh(to);
    glm::vec3 where(0.0f);
    float farthest = -1.0f;
    for (const glm::vec3& p : sample_surface(from, 20000, 1)) {
        const float d = bvh.distance(p);
        if (d > farthest) {
            farthest = d;
            where = p;
        }
    }
    std::printf("    %s: %.2f%% at (%.2f, %.2f, %.2f)\n", label, 100.0 * farthest / height, where.x,
                where.y, where.z);
}

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace

int main(int argc, char** argv) {
    std::size_t budget = 800;
    int reference_resolution = 200;
    bool where = false, fidelity_only = false, compare_heap = false;
    DecimateSettings decimate;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--budget" && i + 1 < argc)
            budget = std::strtoul(argv[++i], nullptr, 10);
        else if (arg == "--quick")
            reference_resolution = 120;
        else if (arg == "--where")
            where = true;
        else if (arg == "--fidelity-only")
            fidelity_only = true;
        else if (arg == "--heap-only")
            decimate.fast_passes = false;
        else if (arg == "--compare-heap")
            compare_heap = true;
        else
            names.push_back(arg);
    }
    if (names.empty())
        for (const TreeTemplate* t : builtin_templates()) names.push_back(t->name);

    std::printf("game budget: trunk + crown <= %zu triangles; reference: resolution %d\n\n", budget,
                reference_resolution);
    std::printf("%-9s %7s %5s %4s %5s %6s %6s %6s %6s | %6s %8s %6s | %s\n", "template", "input",
                "tris", "cuts", "ms", "closed", "mean%", "max%", "haus%", "MC res", "MC tris",
                "ratio", "note");
    for (const std::string& name : names) {
        const TreeTemplate tmpl = load_template(name);
        // Meshed as the export meshes it for this budget (crown resolution, merged blobs).
        MeshOptions options;
        options.budget = budget;
        const Tree tree = generate_tree(tmpl, options);
        TreeBudget b;
        b.total = budget;
        const auto start = std::chrono::steady_clock::now();
        const ReducedTree reduced = reduce_tree(tree, b, decimate);
        const double reduce_ms = ms_since(start);
        const Mesh reference = reference_surface(tmpl, reference_resolution);
        const Fidelity f = measure_tree_fidelity(reduced.trunk, reduced.crown, reference);
        // The other way: how far the fine surface strays from the reduced one (a branch
        // the reduction dropped shows here); the larger max of both is the Hausdorff distance.
        auto hausdorff_of = [&reference](const Fidelity& there, const ReducedTree& r) {
            return std::max(
                there.max_percent,
                measure_tree_loss(r.trunk, r.crown, reference, there.height).max_percent);
        };
        const Mesh* reduced_parts[] = {&reduced.trunk, &reduced.crown};
        const double hausdorff = hausdorff_of(f, reduced);
        const PlainMatch plain =
            fidelity_only ? PlainMatch{}
                          : plain_match(tmpl, reference, f.mean_percent, reference_resolution);
        const bool is_closed = closed(reduced.trunk) && closed(reduced.crown);
        char ratio[16] = "-";
        if (plain.resolution > 0)
            std::snprintf(
                ratio, sizeof ratio, "%.1fx",
                static_cast<double>(plain.triangles) / std::max<std::size_t>(reduced.triangles, 1));
        std::printf("%-9s %7zu %5zu %4d %5.0f %6s %6.3f %6.3f %6.2f | %6d %8zu %6s | %s\n",
                    name.c_str(), tree.trunk.triangles.size() + tree.crown.triangles.size(),
                    reduced.triangles, reduced.handles_cut, reduce_ms, is_closed ? "yes" : "NO",
                    f.mean_percent, f.max_percent, hausdorff, plain.resolution, plain.triangles,
                    ratio, reduced.within_budget ? "" : reduced.note.c_str());
        if (compare_heap) {
            DecimateSettings heap = decimate;
            heap.fast_passes = false;
            const auto heap_start = std::chrono::steady_clock::now();
            const ReducedTree h = reduce_tree(tree, b, heap);
            const double heap_ms = ms_since(heap_start);
            const Fidelity hf = measure_tree_fidelity(h.trunk, h.crown, reference);
            std::printf(
                "%-9s %7s %5zu %4d %5.0f %6s %6.3f %6.3f %6.2f | heap only: %.2fx the "
                "time, mean %+.1f%%\n",
                "  heap", "", h.triangles, h.handles_cut, heap_ms,
                closed(h.trunk) && closed(h.crown) ? "yes" : "NO", hf.mean_percent, hf.max_percent,
                hausdorff_of(hf, h), heap_ms / std::max(reduce_ms, 1e-3),
                100.0 * (f.mean_percent / std::max(hf.mean_percent, 1e-12) - 1.0));
        }
        if (where) {
            std::printf("    trunk %zu -> %zu, crown %zu -> %zu triangles; %zu crown bridges\n",
                        tree.trunk.triangles.size(), reduced.trunk.triangles.size(),
                        tree.crown.triangles.size(), reduced.crown.triangles.size(),
                        tree.crown_bridges);
            print_farthest("reduced -> reference", merge_meshes(reduced_parts), reference,
                           f.height);
            print_farthest("reference -> reduced", reference, merge_meshes(reduced_parts),
                           f.height);
        }
        std::fflush(stdout);
    }

    if (fidelity_only) return 0;
    // Reduction speed: the default tree meshed to about 100k triangles, best of 5.
    TreeTemplate tmpl = default_template();
    Tree tree;
    for (int r = 80; r <= 200; r += 5) {
        tmpl.params.trunk_resolution = r;
        tmpl.params.crown_resolution = r;
        tree = generate_tree(tmpl);
        if (tree.trunk.triangles.size() + tree.crown.triangles.size() >= 100'000) break;
    }
    double best_ms = 1e30, best_cpu_ms = 1e30;
    ReducedTree r;
    TreeBudget b;
    b.total = budget;
    for (int i = 0; i < 5; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const std::clock_t cpu = std::clock();
        r = reduce_tree(tree, b, decimate);
        best_ms = std::min(best_ms, ms_since(start));
        best_cpu_ms = std::min(best_cpu_ms,
                               1000.0 * static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC);
    }
    std::printf(
        "\nreduce %zu triangles (%s at resolution %d) to %zu: %.0f ms wall, %.0f ms CPU "
        "(best of 5; target < 500 ms)\n",
        tree.trunk.triangles.size() + tree.crown.triangles.size(), tmpl.name.c_str(),
        tmpl.params.trunk_resolution, r.triangles, best_ms, best_cpu_ms);
    return 0;
}
