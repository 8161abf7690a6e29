// The reduction alone: finish_tree (trunk + crown decimated to the budget,
// handles cut where needed, leaves thinned) for every built-in template at budgets 200,
// 800 and 3000, each tree meshed as the export meshes it for that budget. The best of
// `--repeat` runs (default 3), as wall time and as the calling thread's CPU time; the CPU
// time is the steadier figure on a shared machine (the reduction runs on one thread).
//
// Columns per budget: ms = best wall time, cpu = best thread CPU time, tris = trunk + crown
// after, cuts = handles cut. Then the median and worst wall time per budget.
//
// Usage: sylva-bench-reduce [--markdown] [--repeat N] [TEMPLATE...]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "bench/common.h"
#include "core/stopwatch.h"
#include "export/export_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

using namespace sylva;

int main(int argc, char** argv) {
    // Its exports, like the studio's, follow each other in one process.
    bench::use_studio_heap();
    int repeat = 3;
    std::vector<std::string> names;
    bool markdown = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (arg == "--markdown")
            markdown = true;
        else
            names.push_back(arg);
    }
    if (names.empty())
        for (const TreeTemplate* t : builtin_templates()) names.push_back(t->name);
    const std::size_t budgets[] = {200, 800, 3000};

    if (!markdown)
        std::printf("reduction (finish_tree), best of %d; ms = wall, cpu = thread CPU\n", repeat);
    std::vector<std::string> header = {"template"};
    for (std::size_t b : budgets)
        for (const char* column : {"ms", "cpu", "tris", "cuts"})
            header.push_back(std::to_string(b) + " " + column);
    bench::Table table(header);
    std::vector<std::vector<double>> walls(std::size(budgets));
    for (const std::string& name : names) {
        const TreeTemplate tmpl = load_template(name);
        std::vector<std::string> cells = {name};
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
                const double cpu = bench::thread_cpu_ms();
                Stopwatch wall;
                finished = finish_tree(tree, finish);
                best_wall = std::min(best_wall, wall.lap_ms());
                best_cpu = std::min(best_cpu, bench::thread_cpu_ms() - cpu);
            }
            const ReducedTree& level = finished.levels.at(0);
            cells.insert(cells.end(),
                         {bench::format("%.1f", best_wall), bench::format("%.1f", best_cpu),
                          std::to_string(level.triangles), std::to_string(level.handles_cut)});
            walls[k].push_back(best_wall);
        }
        table.row(std::move(cells));
    }
    table.print(markdown);
    std::printf("\n");
    bench::Table summary({"budget", "median ms", "worst ms"});
    for (std::size_t k = 0; k < std::size(budgets); ++k)
        summary.row({std::to_string(budgets[k]), bench::format("%.1f", bench::median(walls[k])),
                     bench::format("%.1f", *std::max_element(walls[k].begin(), walls[k].end()))});
    summary.print(markdown);
    return 0;
}
