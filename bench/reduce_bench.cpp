// The reduction alone: finish_tree (trunk + crown decimated to the budget,
// handles cut where needed, leaves thinned) for every built-in template at budgets 200,
// 800 and 3000, each tree meshed as the export meshes it for that budget. The best of
// `--repeat` runs (default 3), as wall time and as the calling thread's CPU time; the CPU
// time is the steadier figure on a shared machine (the reduction runs on one thread).
//
// Columns per budget: ms = best wall time, cpu = best thread CPU time, tris = trunk + crown
// after, cuts = handles cut. Then the median and worst wall time per budget.
//
// Usage: sylva-bench-reduce [--repeat N] [TEMPLATE...]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <limits>
#include <string>
#include <vector>

#include "core/stopwatch.h"
#include "export/export_tree.h"
#include "platform/large_pages.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace {

using namespace sylva;

double thread_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    // The studio's heap (platform/large_pages.h): its exports, like these, follow each other in
    // one process. SYLVA_NO_LARGE_PAGES=1 measures without.
    if (!std::getenv("SYLVA_NO_LARGE_PAGES")) keep_freed_memory();
    int repeat = 3;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else
            names.push_back(arg);
    }
    if (names.empty())
        for (const TreeTemplate* t : builtin_templates()) names.push_back(t->name);
    const std::size_t budgets[] = {200, 800, 3000};

    std::printf("reduction (finish_tree), best of %d; ms = wall, cpu = thread CPU\n", repeat);
    std::printf("%-11s", "template");
    for (std::size_t b : budgets)
        std::printf(" | %4zu: %6s %6s %5s %4s", b, "ms", "cpu", "tris", "cuts");
    std::printf("\n");
    std::vector<std::vector<double>> walls(std::size(budgets));
    for (const std::string& name : names) {
        const TreeTemplate tmpl = load_template(name);
        std::printf("%-11s", name.c_str());
        for (std::size_t k = 0; k < std::size(budgets); ++k) {
            FinishSettings finish;
            finish.budget.total = budgets[k];
            MeshOptions options;
            options.budget = game_budget(finish);
            const Tree tree = generate_tree(tmpl, options);
            double best_wall = std::numeric_limits<double>::max();
            double best_cpu = best_wall;
            FinishedTree finished;
            for (int r = 0; r < repeat; ++r) {
                const double cpu = thread_cpu_ms();
                Stopwatch wall;
                finished = finish_tree(tree, finish);
                best_wall = std::min(best_wall, wall.lap_ms());
                best_cpu = std::min(best_cpu, thread_cpu_ms() - cpu);
            }
            const ReducedTree& level = finished.levels.at(0);
            std::printf(" | %4s  %6.1f %6.1f %5zu %4d", "", best_wall, best_cpu, level.triangles,
                        level.handles_cut);
            walls[k].push_back(best_wall);
        }
        std::printf("\n");
        std::fflush(stdout);
    }
    for (std::size_t k = 0; k < std::size(budgets); ++k)
        std::printf("budget %zu: median %.1f ms, worst %.1f ms\n", budgets[k], median(walls[k]),
                    *std::max_element(walls[k].begin(), walls[k].end()));
    return 0;
}
