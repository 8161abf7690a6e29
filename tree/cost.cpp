#include "tree/cost.h"

#include <oneapi/tbb/parallel_invoke.h>

#include <algorithm>
#include <cstdio>

#include "core/errors.h"
#include "lowpoly/handle_cutting.h"
#include "tree/growth.h"
#include "tree/pipeline.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_growth.h"
#include "turtle/lsystem_params.h"
#include "turtle/lsystem_parser.h"

namespace sylva {
namespace {

// Fitted to `sylva export` and `sylva skeleton` on two cores (docs/cli.md, "Limits"): the
// default template at resolutions 150-450, and F -> FF at 18-21 steps.
constexpr double kBaseBytes = 3.0e7;
constexpr double kBytesPerModule = 40.0;      // the word, twice while deriving
constexpr double kBytesPerSegment = 1300.0;   // skeleton, fields, skeleton.json text
constexpr double kBytesPerCellSquared = 850;  // per resolution^2: the sparse meshes
constexpr double kSecondsPerModule = 2.0e-6;
constexpr double kSecondsPerSegment = 34.0e-6;
constexpr double kMeshSecondsPerCellSquared = 6.0e-6;
// The default template at budget 800 makes about 1.8 resolution^2 raw triangles. Reducing
// a triangle costs more on larger meshes (memory-bound), so the rate is a large mesh's.
constexpr double kReduceSecondsPerCellSquared = 4.0e-6;
constexpr double kReduceSecondsPerTriangle = 2.2e-6;
// Cutting h handles adds about 0.26 us * h^2 (fitted on the ternary tree at generations
// 6-8).
constexpr double kReduceSecondsPerHandleSquared = 2.6e-7;
constexpr double kReduceBytesPerTriangle = 400.0;  // corner table, heap, quadrics, copies
// A finished triangle kept for writing: three corners of position, normal, UV and colour.
constexpr double kKeptBytesPerTriangle = 150.0;

std::string format_number(double n) {
    char text[32];
    if (n < 1e7)
        std::snprintf(text, sizeof text, "%.0f", n);
    else
        std::snprintf(text, sizeof text, "%.2g", n);
    return text;
}

// "1 segment", "1284 segments".
std::string counted(double n, const char* noun) {
    return format_number(n) + " " + noun + (n == 1.0 ? "" : "s");
}

}  // namespace

Cost estimate_cost(const TreeTemplate& tree, std::size_t budget, bool mesh) {
    Cost cost;
    if (tree.growth == lsystem_growth.name) {
        try {
            const LSystem system = parse_lsystem(tree.grammar, param_constants(tree.params));
            const WordGrowth growth = word_growth(system, lsystem_params(tree.params).generations);
            cost.modules = growth.low_modules;
            cost.segments = growth.low_segments;
        } catch (const InputError&) {
            // Generating reports it, with the template's file and line.
        }
    }
    cost.bytes = kBaseBytes + kBytesPerModule * cost.modules;
    cost.seconds = kSecondsPerModule * cost.modules;
    if (const GrowthMethod* method = find_growth_method(tree.growth); method && method->estimate) {
        const GrowthCost growth = method->estimate(tree);
        cost.segments = growth.segments;
        // The growth's memory is gone when the skeleton's is needed: the larger counts.
        cost.bytes = std::max(cost.bytes, kBaseBytes + growth.bytes);
        cost.seconds += growth.seconds;
        cost.growth = growth.work;
    }
    cost.bytes += kBytesPerSegment * cost.segments;
    cost.seconds += kSecondsPerSegment * cost.segments;
    if (mesh) {
        // A game mesh whose branches are prisms meshes no trunk.
        const bool prisms = budget > 0 && branch_style(tree.params) == BranchStyle::Prisms;
        const double trunk = prisms ? 0.0 : trunk_resolution_for_budget(tree.params, budget);
        const double crown = crown_resolution_for_budget(tree.params.crown_resolution, budget);
        const double squared = trunk * trunk + crown * crown;
        cost.cells = trunk * trunk * trunk + crown * crown * crown;
        cost.bytes += kBytesPerCellSquared * squared;
        cost.seconds += kMeshSecondsPerCellSquared * squared;
        if (budget > 0) cost.seconds += kReduceSecondsPerCellSquared * squared;
    }
    return cost;
}

Cost estimate_reduction_cost(const Tree& tree, std::size_t budget) {
    const Mesh none;
    const Mesh& trunk = tree.branch_axes.axes.empty() ? tree.trunk : none;
    const Mesh& crown = tree.crown;
    Cost cost;
    cost.triangles = static_cast<double>(trunk.triangles.size() + crown.triangles.size());
    if (budget == 0 || cost.triangles <= static_cast<double>(budget)) return Cost{};
    std::size_t trunk_handles = 0, crown_handles = 0;
    tbb::parallel_invoke([&] { trunk_handles = genus(trunk); },
                         [&] { crown_handles = genus(crown); });
    cost.handles = static_cast<double>(trunk_handles + crown_handles);
    cost.bytes = kReduceBytesPerTriangle * cost.triangles;
    cost.seconds = kReduceSecondsPerTriangle * cost.triangles +
                   kReduceSecondsPerHandleSquared * cost.handles * cost.handles;
    return cost;
}

Cost many_trees_cost(const Cost& each, double count, std::size_t budget) {
    Cost cost;
    if (!(count > 0.0)) return cost;
    // Trunk + crown, as many leaf triangles, and the LOD levels' half again.
    const double kept = budget > 0 ? kKeptBytesPerTriangle * 3.0 * static_cast<double>(budget)
                                   : std::max(0.0, each.bytes - kBaseBytes);
    cost.modules = each.modules * count;
    cost.segments = each.segments * count;
    cost.cells = each.cells * count;
    cost.triangles = each.triangles * count;
    cost.handles = each.handles * count;
    cost.bytes = each.bytes + kept * count;
    cost.seconds = each.seconds * count;
    return cost;
}

std::string cost_text(const Cost& cost) {
    char tail[96];
    std::snprintf(tail, sizeof tail, "about %.2g GB and %.3g s", cost.bytes / 1e9, cost.seconds);
    std::string text;
    if (!cost.growth.empty()) text += cost.growth + ", ";
    if (cost.modules > 0)
        text += counted(cost.modules, "module") + ", " + counted(cost.segments, "segment") + ", ";
    if (cost.cells > 0) text += counted(cost.cells, "cell") + ", ";
    if (cost.triangles > 0)
        text += counted(cost.triangles, "triangle") + " with " + counted(cost.handles, "handle") +
                " to reduce, ";
    return text + tail;
}

bool within(const Cost& cost, const CostLimits& limits) {
    return cost.bytes <= limits.max_bytes && cost.seconds <= limits.max_seconds;
}

GrowthLimits growth_limits(const CostLimits& limits, const std::string& how_to_override) {
    return {limits.max_seconds, limits.max_bytes, how_to_override};
}

void check_cost(const Cost& cost, const CostLimits& limits, const std::string& how_to_override,
                const std::string& what) {
    if (within(cost, limits)) return;
    char limit[96];
    std::snprintf(limit, sizeof limit, "%.0f MB and %.3g s", limits.max_bytes / 1e6,
                  limits.max_seconds);
    throw InputError(what + " is estimated at " + cost_text(cost) + ", over the limit of " + limit +
                     " (lower the steps, points or resolutions, or " + how_to_override + ")");
}

}  // namespace sylva
