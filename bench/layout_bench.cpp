// Layout grammars on every shipped example: derivation time and what the hierarchy did; 50
// variations at the default sizes (how many differ from the example and from every starter,
// how many distinct structures up to isomorphism of the plane graph, all planar and locally
// similar); variations grown to 2, 5 and 10 times the example's size (how many land within
// 20% of the target); 100 variations at 10 times the size on 2 threads; the same bytes from
// the same seed. Goals: derivation <= 1 s, >= 90% differ, >= 20 distinct structures, sizes
// within 20%, 100 variations at 10x <= 1 s on 2 cores. Times are the best of 3 runs, wall
// clock and CPU (all threads; on a shared machine CPU / threads is the steadier figure).
//   build/bench/sylva-bench-layout [--markdown] [EXAMPLE...]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "bench/common.h"
#include "layout/derive.h"
#include "layout/examples.h"
#include "layout/generate.h"
#include "layout/similarity.h"
#include "layout/variations.h"

using namespace sylva::layout;
using sylva::bench::Times;

int main(int argc, char** argv) {
    std::vector<std::string> names(argv + 1, argv + argc);
    const bool markdown = sylva::bench::take_flag(names, "--markdown");
    if (names.empty())
        for (const auto& [name, text] : builtin_examples()) names.push_back(name);
    std::printf("layout grammars: derivation and 100 variations at 10x best of 3, ms\n");
    sylva::bench::Table rows({"example", "derive ms", "derive cpu ms", "rules", "starters",
                              "generations", "stopped", "open", "measure", "differ", "distinct",
                              "valid", "relaxed", "within 20% at 2/5/10x", "100 at 10x ms",
                              "100 at 10x cpu/2 ms", "same bytes"});
    bool all_derive = true, all_differ = true, all_distinct = true, all_sizes = true,
         all_fast = true, all_same = true, all_valid = true;
    std::vector<std::string> exempt, short_of, corners;
    Times worst_derive{0, 0}, worst_hundred{0, 0};
    auto max = [](const Times& a, const Times& b) {
        return Times{std::max(a.wall_ms, b.wall_ms), std::max(a.cpu_ms, b.cpu_ms)};
    };
    for (const std::string& name : names) {
        const Example ex = make_example(load_example(name));
        Grammar grammar;
        const Times derive = sylva::bench::best_of(3, [&] { grammar = derive_grammar(ex); });
        const GrowthTable table(grammar);
        const bool grows = table.can_grow();
        // 50 variations at the default sizes.
        VariationSettings defaults;
        VariationsReport report;
        const std::vector<PolygonMesh> layouts = generate_layouts(table, 50, 1, defaults, &report);
        std::set<std::vector<int>> trivial{canonical_code(ex.graph)};
        for (const AngleGraph& s : grammar.starters) trivial.insert(canonical_code(s));
        std::set<std::vector<int>> distinct;
        int differ = 0, valid = 0, relaxed = 0;
        for (std::size_t i = 0; i < layouts.size(); ++i) {
            PolygonMesh copy = layouts[i];
            bool ok = locally_similar(ex, copy);
            try {
                validate_mesh(copy, name);
            } catch (const std::exception&) {
                ok = false;
            }
            valid += ok;
            const std::vector<int> key = structure_key(ex, layouts[i]);
            distinct.insert(key);
            differ += !trivial.count(key);
            relaxed += report.items[i].relax > 0;
        }
        // Sizes: 2, 5 and 10 times the example's, 10 seeds each.
        std::string within;
        bool sizes_ok = true;
        for (int factor : {2, 5, 10}) {
            VariationSettings sized;
            sized.size = factor * table.example_size();
            VariationsReport r;
            generate_layouts(table, 10, 7, sized, &r);
            int in = 0;
            for (const VariationReport& item : r.items)
                in += std::abs(item.size - sized.size) <= 0.2 * sized.size;
            within += (within.empty() ? "" : "/") + std::to_string(in * 10) + "%";
            sizes_ok = sizes_ok && in == 10;
        }
        // 100 at 10x on two threads.
        VariationSettings big;
        big.size = 10 * table.example_size();
        big.threads = 2;
        const Times hundred =
            sylva::bench::best_of(3, [&] { generate_layouts(table, 100, 3, big); });
        // The same bytes from the same seed.
        bool same = true;
        {
            const auto a = generate_layouts(table, 10, 42, defaults);
            VariationSettings one_thread = defaults;
            one_thread.threads = 1;
            const auto b = generate_layouts(table, 10, 42, one_thread);
            for (std::size_t i = 0; i < a.size(); ++i)
                same = same && write_mesh_json(a[i]) == write_mesh_json(b[i]);
        }
        const HierarchyReport& h = grammar.hierarchy;
        auto* f = &sylva::bench::format;
        rows.row({name, f("%.0f", derive.wall_ms), f("%.0f", derive.cpu_ms),
                  std::to_string(grammar.rules.size()), std::to_string(grammar.starters.size()),
                  std::to_string(h.generations), h.stopped_by, std::to_string(h.open_graphs),
                  measure_name(table.measure()), f("%d%%", differ * 2),
                  std::to_string(distinct.size()), f("%d%%", valid * 2), f("%d%%", relaxed * 2),
                  within, f("%.0f", hundred.wall_ms), f("%.0f", hundred.cpu_ms / 2.0),
                  same ? "yes" : "NO"});
        worst_derive = max(worst_derive, derive);
        worst_hundred = max(worst_hundred, hundred);
        all_derive = all_derive && std::min(derive.wall_ms, derive.cpu_ms) <= 1000;
        all_fast = all_fast && std::min(hundred.wall_ms, hundred.cpu_ms / 2.0) <= 1000;
        all_same = all_same && same;
        all_valid = all_valid && valid == 50;
        if (!grows) {
            exempt.push_back(name);
            continue;
        }
        all_differ = all_differ && differ >= 45;
        all_distinct = all_distinct && distinct.size() >= 20;
        if (!sizes_ok) short_of.push_back(name);
        all_sizes = all_sizes && sizes_ok;
        if (table.measure() == SizeMeasure::Corners) corners.push_back(name);
    }
    rows.print(markdown);
    for (const std::string& n : corners)
        std::printf("%s: its rules never add a polygon; sizes count corners\n", n.c_str());
    auto verdict = [](bool ok) { return ok ? "met" : "NOT met"; };
    auto* f = &sylva::bench::format;
    std::string short_names;
    for (const std::string& n : short_of)
        short_names += (short_names.empty() ? "short: " : ", ") + n;
    std::printf("\n");
    sylva::bench::Table goals({"goal", "met", "figure"});
    goals.row({"derivation <= 1 s", verdict(all_derive),
               f("slowest %.0f ms wall, %.0f ms CPU", worst_derive.wall_ms, worst_derive.cpu_ms)});
    goals.row({">= 90% differ from the example and every starter", verdict(all_differ), ""});
    goals.row({">= 20 distinct structures of 50", verdict(all_distinct), ""});
    goals.row({"every output planar and locally similar", verdict(all_valid), ""});
    goals.row({"sizes within 20% of 2, 5 and 10 x the example", verdict(all_sizes), short_names});
    goals.row({"100 variations at 10x <= 1 s on 2 threads", verdict(all_fast),
               f("slowest %.0f ms wall, %.0f ms CPU / 2", worst_hundred.wall_ms,
                 worst_hundred.cpu_ms / 2.0)});
    goals.row({"same bytes from the same seed", verdict(all_same), ""});
    goals.print(markdown);
    std::printf("exempt (the grammar is only its starter):");
    for (const std::string& n : exempt) std::printf(" %s", n.c_str());
    std::printf("\n");
    return 0;
}
