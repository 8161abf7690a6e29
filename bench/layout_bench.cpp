// Layout grammars: derivation time and grammar size of every shipped example,
// and the time to generate 100 variations of the largest. Goals: derivation < 1 s each,
// 100 variations < 1 s.
#include <chrono>
#include <cstdio>

#include "layout/graph_grammar.h"
#include "layout/layout_cli.h"
#include "layout/positions.h"

int main() {
    using namespace sylva::layout;
    using clock = std::chrono::steady_clock;
    auto ms = [](clock::time_point a, clock::time_point b) {
        return std::chrono::duration<double, std::milli>(b - a).count();
    };
    std::printf("%-15s %8s %10s %9s %9s %6s %10s %6s\n", "example", "vertices", "primitives",
                "starters", "rules", "graphs", "open", "ms");
    std::string largest;
    std::size_t largest_vertices = 0;
    double worst = 0;
    for (const auto& [name, text] : builtin_examples()) {
        const Example ex = make_example(read_mesh_text(text, name));
        const auto t0 = clock::now();
        const Grammar g = derive_grammar(ex);
        const double t = ms(t0, clock::now());
        worst = std::max(worst, t);
        std::printf("%-15s %8zu %10zu %9zu %9zu %6d %10d %6.1f\n", name.c_str(),
                    ex.graph.vertices.size(), g.primitives.size(), g.starters.size(),
                    g.rules.size(), g.hierarchy_graphs, g.open_graphs, t);
        if (ex.graph.vertices.size() > largest_vertices)
            largest_vertices = ex.graph.vertices.size(), largest = name;
    }
    std::printf("slowest derivation: %.1f ms (goal < 1000 ms)\n", worst);
    const Grammar g = derive_grammar(make_example(load_example(largest)));
    const auto t0 = clock::now();
    const auto layouts = generate_layouts(g, 100, 1);
    const double t = ms(t0, clock::now());
    std::size_t polygons = 0;
    for (const auto& m : layouts) polygons += m.polygons.size();
    std::printf("100 variations of %s: %.1f ms, %.1f polygons each (goal < 1000 ms)\n",
                largest.c_str(), t, static_cast<double>(polygons) / 100.0);
    return 0;
}
