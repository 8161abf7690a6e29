#include "layout/cost.h"

#include <tbb/info.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sylva::layout {

namespace {

std::string figure(double n) {
    char text[32];
    std::snprintf(text, sizeof text, n < 1e7 ? "%.0f" : "%.3g", n);
    return text;
}

}  // namespace

LayoutCost derive_cost(const Example& example, const DeriveSettings& settings) {
    // Each hierarchy graph costs a canonical code, a planarity test and a boundary
    // decomposition, all growing with the graph's size, which grows with the generation; a
    // star with many darts makes many children per graph. The primitives cost the example's
    // size once.
    const double vertices = static_cast<double>(example.graph.vertices.size());
    double degree = 0;
    for (const auto& ds : example.graph.vertices)
        degree = std::max(degree, static_cast<double>(ds.size()));
    const double graphs = settings.max_graphs > 0 ? settings.max_graphs : 1e9;
    double seconds = 2e-6 * vertices + graphs * 40e-6 * (1.0 + degree / 8.0);
    if (settings.max_seconds > 0) seconds = std::min(seconds, settings.max_seconds + 0.1);
    LayoutCost c;
    c.seconds = seconds;
    c.bytes = 600.0 * vertices + graphs * 4000.0;
    c.what = figure(graphs) + " hierarchy graphs";
    return c;
}

LayoutCost generate_cost(const GrowthTable& table, int count, const VariationSettings& settings) {
    const Grammar& g = table.grammar();
    const double base = std::max(1, table.example_size());
    // Edges per unit of size, from the example (a planar example has about E = V + F).
    const double example_edges = g.example_vertices + g.example_polygons;
    const double edges_per_unit = example_edges / base;
    double size = settings.size > 0 ? settings.size
                                    : (settings.spread_high > 0 ? settings.spread_high : 12 * base);
    if (settings.area > 0) {
        double area_per_unit = 0;
        for (const auto& [label, length] : g.dirs.label_length)
            area_per_unit = std::max(area_per_unit, length * length);
        size = std::max(size, settings.area / std::max(area_per_unit, 1e-9) * 2.0);
    }
    const double edges = std::max(4.0, size * edges_per_unit);
    // Growing: about `size` moves, each a planarity test of the graph; drawing: Gauss-Jordan
    // and Gram-Schmidt over (2 x faces) x edges, tried a few times.
    const double each = 2e-7 * size * edges + 4e-9 * edges * edges * edges + 2e-4;
    const double threads =
        settings.threads > 0 ? settings.threads : std::max(1, tbb::info::default_concurrency());
    LayoutCost c;
    c.seconds = each * std::max(0, count) / std::min<double>(threads, std::max(1, count));
    c.bytes = threads * 24.0 * edges * edges + count * edges * 200.0 + 1e6;
    c.what =
        figure(count) + " layouts of up to " + figure(size) + " " + measure_name(table.measure());
    return c;
}

LayoutCost operator+(const LayoutCost& a, const LayoutCost& b) {
    LayoutCost c;
    c.seconds = a.seconds + b.seconds;
    c.bytes = std::max(a.bytes, b.bytes);
    c.what = a.what.empty() ? b.what : (b.what.empty() ? a.what : a.what + " and " + b.what);
    return c;
}

}  // namespace sylva::layout
