// Space colonization to a finished skeleton (targets: 10,000 points <= 20 ms,
// 100,000 points <= 200 ms), the grid against the brute-force nearest-node reference in
// the same run. Prints the times, the ratio, and whether both grew the same tree.
//   build/bench/sylva-bench-colonization [--markdown] [repeats]
// With --cost, the cost model instead (colonization/colonization_cost.h): per crown and
// point count, the estimate before the run against the counted work and the run's thread
// CPU time (best of three), and their ratios; --large adds a million points.
//   build/bench/sylva-bench-colonization --cost [--large]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "bench/common.h"
#include "colonization/attraction_points.h"
#include "colonization/branch_shaping.h"
#include "colonization/colonization_cost.h"
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

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct CostCase {
    const char* name;
    Envelope envelope;
    ColonizationSettings settings;
    int points;
};

// The shipped colonization crowns' shapes and settings (elm, hedge), and what makes them
// costly: many points, a kill distance far below the step, a small step.
std::vector<CostCase> cost_cases(bool large) {
    Envelope elm;
    elm.shape = EnvelopeShape::Ellipsoid;
    elm.size = {9.0f, 5.5f, 9.0f};
    elm.base = {0.0f, 4.0f, 0.0f};
    ColonizationSettings elm_s;
    elm_s.influence_radius = 2.2f;
    elm_s.kill_distance = 0.7f;
    elm_s.step_size = 0.4f;
    elm_s.trunk_height = 3.0f;
    elm_s.max_iterations = 200;
    elm_s.max_degree = 3;
    Envelope hedge;
    hedge.shape = EnvelopeShape::Cylinder;
    hedge.size = {4.0f, 1.5f, 1.4f};
    hedge.base = {0.0f, 0.1f, 0.0f};
    ColonizationSettings hedge_s;
    hedge_s.influence_radius = 1.2f;
    hedge_s.kill_distance = 0.35f;
    hedge_s.step_size = 0.2f;
    hedge_s.max_iterations = 200;
    hedge_s.max_depth = 6;
    hedge_s.max_no_grow = 12;
    auto with = [](ColonizationSettings s, float kill, float step) {
        if (kill > 0.0f) s.kill_distance = kill;
        if (step > 0.0f) s.step_size = step;
        return s;
    };
    std::vector<CostCase> cases = {
        {"elm", elm, elm_s, 1400},
        {"elm", elm, elm_s, 100000},
        {"elm, step 0.05", elm, with(elm_s, 0, 0.05f), 1400},
        {"elm, step 0.01", elm, with(elm_s, 0, 0.01f), 100000},
        {"elm, kill 0.2", elm, with(elm_s, 0.2f, 0), 100000},
        {"elm, kill 0.01", elm, with(elm_s, 0.01f, 0), 20000},
        {"elm, kill 0.01", elm, with(elm_s, 0.01f, 0), 100000},
        {"hedge", hedge, hedge_s, 1200},
        {"hedge, kill 0.01", hedge, with(hedge_s, 0.01f, 0), 30000},
    };
    if (large) cases.push_back({"elm, kill 0.001", elm, with(elm_s, 0.001f, 0), 1000000});
    return cases;
}

int cost_table(bool large) {
    std::printf("%-18s %8s | %9s %9s %8s | %9s %9s %8s %8s | %6s %6s %6s\n", "crown", "points",
                "est nodes", "visits", "s", "nodes", "visits", "counted", "cpu s", "nodes",
                "visits", "s");
    for (const CostCase& c : cost_cases(large)) {
        const std::vector<glm::vec3> points =
            attraction_points(c.envelope, c.points, PointDistribution::Uniform, 3);
        const ColonizationCost estimate =
            estimate_colonization_cost(bounds(c.envelope), points.size(), 1, c.settings);
        ColonizationGraph graph;
        double best = 1e30;
        for (int i = 0; i < 3; ++i) {
            const double start = thread_cpu_seconds();
            graph = colonize(points, glm::vec3(0.0f), c.settings);
            best = std::min(best, thread_cpu_seconds() - start);
            if (best > 10.0) break;  // one run is figure enough
        }
        const ColonizationCost counted =
            colonization_cost(graph.work, points.size(), bounds(c.envelope), c.settings);
        const double nodes = static_cast<double>(graph.work.nodes);
        const double visits = static_cast<double>(graph.work.visits);
        std::printf(
            "%-18s %8zu | %9.0f %9.2g %8.3g | %9.0f %9.2g %8.3g %8.3g | %6.2f %6.2f %6.2f\n",
            c.name, points.size(), estimate.nodes, estimate.visits, estimate.seconds, nodes, visits,
            counted.seconds, best, estimate.nodes / nodes, estimate.visits / visits,
            estimate.seconds / best);
        std::fflush(stdout);
    }
    std::printf(
        "(estimate | counted, with the model's seconds, and the run's CPU time | "
        "ratios estimate / run)\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--cost") == 0)
        return cost_table(argc > 2 && std::strcmp(argv[2], "--large") == 0);
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
