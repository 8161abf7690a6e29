// Reproduces Heuer's (2022) table 6.1 (marching cubes on its spruce, appendix B.1) and measures
// Sylva's meshers against it, on this machine, in one run:
//   baseline  Heuer's way: 8 field evaluations per cube, every primitive, all threads
//   dense     Sylva's marching cubes, every grid node once, culled field, all threads
//   sparse    Sylva's marching cubes skipping blocks the distance bound proves empty
//   vdb       OpenVDB narrow band + tools::volumeToMesh
// Peak memory is measured in a forked child per configuration (ru_maxrss).
//
// Usage: sylva-bench-mesh [--quick] [--markdown]
//   --quick: resolutions up to 100, one repetition; --markdown: the table as Markdown
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "bench/common.h"
#include "core/mesh_checks.h"
#include "marching/grid.h"
#include "marching/mesher.h"
#include "sdf/capped_cone.h"
#include "sdf/sphere_field.h"
#include "tree/growth.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace {

using namespace sylva;

struct SeedRow {
    int resolution;
    double trunk_s, crown_s;  // MCA_opt, 16 threads (Heuer 2022, table 6.1)
    int trunk_triangles, crown_triangles;
};
constexpr SeedRow kSeed[] = {
    {25, 0.05, 0.02, 942, 3848},      {50, 0.4, 0.2, 6452, 15992},
    {75, 1.1, 0.43, 14196, 36268},    {100, 2.5, 1.0, 27100, 64476},
    {125, 4.4, 1.9, 40738, 101668},   {150, 7.8, 3.3, 60472, 146604},
    {200, 17.9, 7.8, 111026, 259556},
};

const SeedRow* seed_row(int resolution) {
    for (const SeedRow& r : kSeed)
        if (r.resolution == resolution) return &r;
    return nullptr;
}

double seconds_of(const std::function<void()>& f) {
    auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double best_of(int repetitions, const std::function<void()>& f) {
    double best = std::numeric_limits<double>::max();
    for (int i = 0; i < repetitions; ++i) best = std::min(best, seconds_of(f));
    return best;
}

// Peak resident memory (MB) of a child process that runs f.
double peak_mb_in_child(const std::function<void()>& f) {
    std::fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        f();
        _exit(0);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// One part of the tree (trunk or crown) as the meshers and the baseline see it.
struct Part {
    const char* name;
    Box box;
    std::function<float(const glm::vec3&)> culled;       // Sylva's field
    std::function<float(const glm::vec3&)> brute_force;  // every primitive, as Heuer 2022 does
};

BatchField batch_of(const std::function<float(const glm::vec3&)>& f) {
    return [&f](std::span<const glm::vec3> points, std::span<float> values) {
        for (size_t i = 0; i < points.size(); ++i) values[i] = f(points[i]);
    };
}

// Heuer's (2022) marching cubes cost: every cube evaluates its 8 corners with every primitive.
// Returns the number of cubes the surface crosses (the triangles themselves are not built:
// their cost is negligible next to the evaluations).
std::size_t baseline(const Part& part, int resolution) {
    MeshSettings settings;
    settings.resolution = resolution;
    Grid grid = make_grid(part.box, settings);
    std::atomic<std::size_t> crossing{0};
    const int cubes_z = grid.nodes[2] - 1;
    tbb::parallel_for(tbb::blocked_range<int>(0, cubes_z), [&](const tbb::blocked_range<int>& r) {
        std::size_t local = 0;
        for (int k = r.begin(); k != r.end(); ++k)
            for (int j = 0; j + 1 < grid.nodes[1]; ++j)
                for (int i = 0; i + 1 < grid.nodes[0]; ++i) {
                    int inside = 0;
                    for (int c = 0; c < 8; ++c) {
                        glm::vec3 p(grid.node(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1)));
                        inside += part.brute_force(p) < 0.0f;
                    }
                    local += inside != 0 && inside != 8;
                }
        crossing += local;
    });
    return crossing;
}

struct Measure {
    double seconds = 0;
    std::size_t triangles = 0;
    std::size_t evaluations = 0;
    bool closed = false;
};

Measure run_mesher(Mesher mesher, const Part& part, int resolution, int repetitions) {
    Measure m;
    BatchField field = batch_of(part.culled);
    Mesh mesh;
    MeshingStats stats;
    MeshSettings settings;
    settings.mesher = mesher;
    settings.resolution = resolution;
    settings.stats = &stats;
    m.seconds = best_of(repetitions, [&] {
        stats = {};
        mesh = sylva::mesh(field, part.box, settings);
    });
    m.triangles = mesh.triangles.size();
    m.evaluations = stats.evaluations;
    m.closed = check_topology(mesh).is_closed_manifold();
    return m;
}

std::vector<Part> tree_parts(const TreeFields& fields) {
    std::vector<Part> parts;
    const ConeField& trunk = *fields.trunk;
    parts.push_back({"trunk", fields.trunk_box, [&trunk](const glm::vec3& p) { return trunk(p); },
                     [&trunk](const glm::vec3& p) { return union_distance(trunk.cones(), p); }});
    if (fields.crown) {
        const SphereField& crown = *fields.crown;
        parts.push_back({"crown", fields.crown_box,
                         [&crown](const glm::vec3& p) { return crown(p); },
                         [&crown](const glm::vec3& p) {
                             // Heuer 2022 folds its root smooth min over every sphere.
                             float d = std::numeric_limits<float>::max();
                             bool first = true;
                             for (const Ball& b : crown.balls()) {
                                 float next = distance(b, p);
                                 d = first ? next : root_smooth_min(d, next, crown.blend());
                                 first = false;
                             }
                             return d;
                         }});
    }
    return parts;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    const bool quick = bench::take_flag(args, "--quick");
    const bool markdown = bench::take_flag(args, "--markdown");
    const int repetitions = quick ? 1 : 3;
    std::vector<int> resolutions = {25, 50, 75, 100, 125, 150, 200, 300, 400};
    if (quick) resolutions = {25, 50, 100};

    TreeTemplate spruce = load_template("seed_spruce");
    Skeleton skeleton = grow(spruce);
    std::printf(
        "Heuer's spruce (appendix B.1): %zu segments, %zu tips; %u hardware threads; "
        "times best of %d, seconds\n\n",
        skeleton.segments.size(), tips(skeleton).size(),
        std::max(1u, std::thread::hardware_concurrency()), repetitions);
    bench::Table table({"part", "res", "thesis s", "thesis tri", "baseline", "dense", "sparse",
                        "triangles", "evals", "ev/tri", "vdb", "vdb tri", "x base", "x thesis",
                        "MB", "closed"});

    double total_200 = 0;
    for (int resolution : resolutions) {
        TreeParams params = spruce.params;
        params.trunk_resolution = params.crown_resolution = resolution;
        TreeFields fields = tree_fields(skeleton, params);
        for (const Part& part : tree_parts(fields)) {
            const bool is_trunk = std::strcmp(part.name, "trunk") == 0;
            const SeedRow* seed = seed_row(resolution);
            double base = resolution <= 200 ? seconds_of([&] { baseline(part, resolution); }) : 0;
            Measure dense = run_mesher(Mesher::Dense, part, resolution, repetitions);
            Measure sparse = run_mesher(Mesher::Sparse, part, resolution, repetitions);
            Measure vdb = run_mesher(Mesher::Vdb, part, resolution, repetitions);
            double mb = peak_mb_in_child([&] { run_mesher(Mesher::Sparse, part, resolution, 1); });
            if (resolution == 200) total_200 += sparse.seconds;
            char seed_s[16] = "-", seed_tri[16] = "-", base_s[16] = "-", x_base[16] = "-",
                 x_seed[16] = "-";
            if (seed) {
                double s = is_trunk ? seed->trunk_s : seed->crown_s;
                std::snprintf(seed_s, sizeof seed_s, "%.2f", s);
                std::snprintf(seed_tri, sizeof seed_tri, "%d",
                              is_trunk ? seed->trunk_triangles : seed->crown_triangles);
                std::snprintf(x_seed, sizeof x_seed, "%.0f", s / sparse.seconds);
            }
            if (base > 0) {
                std::snprintf(base_s, sizeof base_s, "%.3f", base);
                std::snprintf(x_base, sizeof x_base, "%.0f", base / sparse.seconds);
            }
            table.row({part.name, std::to_string(resolution), seed_s, seed_tri, base_s,
                       bench::format("%.4f", dense.seconds), bench::format("%.4f", sparse.seconds),
                       std::to_string(sparse.triangles), std::to_string(sparse.evaluations),
                       bench::format("%.1f", double(sparse.evaluations) /
                                                 double(std::max<size_t>(1, sparse.triangles))),
                       bench::format("%.4f", vdb.seconds), std::to_string(vdb.triangles), x_base,
                       x_seed, bench::format("%.0f", mb),
                       dense.closed && sparse.closed && vdb.closed ? "yes" : "NO"});
        }
    }
    table.print(markdown);
    if (!quick)
        std::printf(
            "\nresolution 200, trunk + crown, sparse: %.1f ms (target < 100 ms; Heuer: "
            "25.7 s on 16 threads)\n",
            total_200 * 1000);

    TreeTemplate tree = default_template();
    tree.params.trunk_resolution = tree.params.crown_resolution = 64;
    Skeleton default_skeleton = grow(tree);
    TreeFields fields = tree_fields(default_skeleton, tree.params);
    double total = 0;
    for (const Part& part : tree_parts(fields))
        total += run_mesher(Mesher::Sparse, part, 64, std::max(repetitions, 5)).seconds;
    std::printf("default tree, resolution 64, trunk + crown, sparse: %.1f ms (target < 10 ms)\n",
                total * 1000);
    std::printf(
        "\nthesis = Heuer's table 6.1 (MCA_opt, 16 threads); baseline = the thesis's method on "
        "this machine;\nx base / x thesis = baseline or thesis time over Sylva's sparse time; "
        "ev/tri = sparse field evaluations per triangle;\n"
        "MB = peak resident memory of a process meshing that part with the sparse mesher.\n");
    return 0;
}
