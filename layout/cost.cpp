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
    // decomposition, tens of microseconds at the sizes a budget reaches; a star with many
    // darts makes many children per graph. The primitives come first, whatever the budget.
    const double vertices = static_cast<double>(example.graph.vertices.size());
    double degree = 0;
    for (const auto& ds : example.graph.vertices)
        degree = std::max(degree, static_cast<double>(ds.size()));
    const double graphs = (settings.max_graphs > 0 ? settings.max_graphs : 1e9) + vertices;
    double seconds = 5e-6 * vertices + graphs * 40e-6 * (1.0 + degree / 8.0);
    if (settings.max_seconds > 0) seconds = std::min(seconds, settings.max_seconds + 0.1);
    LayoutCost c;
    c.seconds = seconds;
    c.bytes = 2000.0 * vertices + graphs * 4000.0;
    c.what = figure(graphs - vertices) + " hierarchy graphs";
    return c;
}

LayoutCost generate_cost(const GrowthTable& table, int count, const VariationSettings& settings) {
    const Grammar& g = table.grammar();
    const double base = std::max(1, table.example_size());
    // Edges and faces per unit of size, from the example (a planar example has about
    // E = V + F edges).
    const double example_edges = g.example_vertices + g.example_polygons;
    const double per_unit = example_edges / base;
    double size = settings.size > 0 ? settings.size
                                    : (settings.spread_high > 0 ? settings.spread_high : 12 * base);
    if (settings.area > 0) {
        double least = 1e300;
        for (const auto& [label, length] : g.dirs.label_length) least = std::min(least, length);
        const double area_per_unit = least * least;
        size = std::max(size, settings.area / std::max(area_per_unit, 1e-9));
    }
    double edges = std::max(4.0, size * per_unit);
    double rows = 2.0 * (table.measure() == SizeMeasure::Polygons ? size : 1.0);
    if (!table.can_grow()) {  // every variation is a starter: the largest is the cost
        edges = rows = 0;
        for (const AngleGraph& s : g.starters) {
            const double e = s.edges();
            if (e > edges) edges = e, rows = 2.0 * (e - static_cast<double>(s.vertices.size()) + 1);
        }
        size = 1;
    }
    const double free = std::max(1.0, edges - rows);
    // Growing: about `size` moves, each a planarity test of the graph. Drawing: Gauss-Jordan
    // (rows^2 x edges) and Gram-Schmidt (free^2 x edges) for the null space, a few tries.
    const double each =
        2e-7 * size * edges + 2e-9 * (rows * rows * edges + free * free * edges) + 4e-4;
    const double threads =
        settings.threads > 0 ? settings.threads : std::max(1, tbb::info::default_concurrency());
    LayoutCost c;
    c.seconds = each * std::max(0, count) / std::min<double>(threads, std::max(1, count));
    c.bytes = threads * 8.0 * (rows + free) * edges + count * edges * 200.0 + 1e6;
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
