// Space colonization to a finished skeleton (targets: 10,000 points <= 20 ms,
// 100,000 points <= 200 ms), the grid against the brute-force nearest-node reference in
// the same run. Prints the times, the ratio, and whether both grew the same tree.
//   build/bench/sylva-bench-colonization [--markdown] [repeats]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/common.h"
#include "colonization/attraction_points.h"
#include "colonization/branch_shaping.h"
#include "colonization/space_colonization.h"
#include "core/stopwatch.h"

using namespace sylva;

namespace {

struct Run {
    double ms = 0.0;
    size_t nodes = 0, segments = 0, remaining = 0;
    int iterations = 0;
};

// Points to a finished skeleton: placement, growth, shaping and Murray radii.
Run run(const Envelope& envelope, int count, const ColonizationSettings& settings) {
    Stopwatch clock;
    const auto points = attraction_points(envelope, count, PointDistribution::Uniform, 1);
    ColonizationGraph graph = colonize(points, glm::vec3(0.0f), settings);
    Run r;
    r.nodes = graph.nodes.size();
    r.remaining = graph.remaining.size();
    r.iterations = graph.iterations;
    draw_successors_together(graph, 0.3f);
    reduce_curves(graph, 0.995f);
    r.segments = to_skeleton(graph, 0.01f, 2.5f).segments.size();
    r.ms = clock.lap_ms();
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    const bool markdown = bench::take_flag(args, "--markdown");
    const int repeats = args.empty() ? 5 : std::max(1, std::atoi(args[0].c_str()));
    // An elm-sized crown: 8 m wide, 6 m tall, on a 3 m trunk.
    Envelope envelope;
    envelope.shape = EnvelopeShape::Ellipsoid;
    envelope.size = {8.0f, 6.0f, 8.0f};
    envelope.base = {0.0f, 3.0f, 0.0f};
    ColonizationSettings settings;
    settings.influence_radius = 1.2f;
    settings.kill_distance = 0.3f;
    settings.step_size = 0.2f;
    settings.trunk_height = 3.0f;
    settings.max_iterations = 1000;
    bench::Table table({"points", "nodes", "segments", "left", "iterations", "grid ms",
                        "brute force ms", "ratio", "same tree"});
    for (int count : {10000, 100000}) {
        double best = 1e30;
        Run grid;
        for (int i = 0; i < repeats; ++i) {
            grid = run(envelope, count, settings);
            best = std::min(best, grid.ms);
        }
        ColonizationSettings reference = settings;
        reference.search = NearestSearch::BruteForce;
        const Run brute = run(envelope, count, reference);  // once: it is slow
        const bool same = brute.nodes == grid.nodes && brute.remaining == grid.remaining;
        table.row({std::to_string(count), std::to_string(grid.nodes), std::to_string(grid.segments),
                   std::to_string(grid.remaining), std::to_string(grid.iterations),
                   bench::format("%.1f", best), bench::format("%.1f", brute.ms),
                   bench::format("%.1fx", brute.ms / best), same ? "yes" : "NO"});
    }
    table.print(markdown);
    return 0;
}
