#include "infer/fit_report.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "infer/branch_graph.h"
#include "tree/growth.h"

namespace sylva {

Skeleton example_skeleton_with_depths(const ExampleTree& example) {
    Skeleton copy = example.skeleton;
    bool missing = false;
    for (const Segment& s : copy.segments) missing = missing || s.depth < 0;
    if (!missing) return copy;
    const BranchGraph g = build_branch_graph(copy, example.continuation);
    for (std::size_t i = 0; i < copy.segments.size(); ++i)
        copy.segments[i].depth = g.axes[static_cast<std::size_t>(g.axis_of[i])].order;
    return copy;
}

double relative_difference(double a, double b) {
    if (a == 0.0) return b == 0.0 ? 0.0 : 1.0;
    return std::abs(b - a) / std::abs(a);
}

FitReport fit_report(const ExampleTree& example, const InferredTemplate& inferred,
                     Skeleton* regrown, const GrowthContext& context) {
    const Skeleton original = example_skeleton_with_depths(example);
    Skeleton grown = grow(inferred.tree, context);
    FitReport r;
    r.example = skeleton_figures(original);
    r.regrown = skeleton_figures(grown);
    r.hausdorff = skeleton_hausdorff(original, grown);
    r.rules = inferred.rules;
    r.modules = inferred.modules;
    r.within_rule_limit = inferred.within_rule_limit;
    r.segments_per_step = inferred.segments_per_step;
    r.generalised = inferred.generalised;
    r.dropped = inferred.dropped;
    if (regrown) *regrown = std::move(grown);
    return r;
}

namespace {

std::string percent(double a, double b) {
    char text[64];
    std::snprintf(text, sizeof text, "%+.1f %%", a == 0.0 ? 0.0 : 100.0 * (b - a) / a);
    return text;
}

}  // namespace

std::string fit_report_text(const FitReport& r) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "  rules: %d in %d modules%s\n", r.rules, r.modules,
                  r.within_rule_limit ? "" : " (more than the limit)");
    out += line;
    out += "  fit (example -> regrown):\n";
    std::snprintf(line, sizeof line, "    segments      %zu -> %zu (%s)\n", r.example.segments,
                  r.regrown.segments,
                  percent(double(r.example.segments), double(r.regrown.segments)).c_str());
    out += line;
    std::snprintf(line, sizeof line, "    total length  %.2f -> %.2f m (%s)\n",
                  r.example.total_length, r.regrown.total_length,
                  percent(r.example.total_length, r.regrown.total_length).c_str());
    out += line;
    std::snprintf(line, sizeof line, "    height        %.2f -> %.2f m (%s)\n", r.example.height,
                  r.regrown.height, percent(r.example.height, r.regrown.height).c_str());
    out += line;
    std::snprintf(line, sizeof line, "    crown width   %.2f -> %.2f m (%s)\n",
                  r.example.crown_width, r.regrown.crown_width,
                  percent(r.example.crown_width, r.regrown.crown_width).c_str());
    out += line;
    out += "    per depth    ";
    const std::size_t depths = std::max(r.example.per_depth.size(), r.regrown.per_depth.size());
    for (std::size_t d = 0; d < depths; ++d) {
        const std::size_t a = d < r.example.per_depth.size() ? r.example.per_depth[d] : 0;
        const std::size_t b = d < r.regrown.per_depth.size() ? r.regrown.per_depth[d] : 0;
        std::snprintf(line, sizeof line, " %zu:%zu->%zu", d, a, b);
        out += line;
    }
    out += "\n";
    std::snprintf(line, sizeof line, "    hausdorff     %.3f m (%.1f %% of the height)\n",
                  r.hausdorff,
                  r.example.height > 0.0 ? 100.0 * r.hausdorff / r.example.height : 0.0);
    out += line;
    if (!r.generalised.empty()) out += "  generalised:\n";
    for (const std::string& g : r.generalised) out += "    - " + g + "\n";
    if (!r.dropped.empty()) out += "  dropped:\n";
    for (const std::string& d : r.dropped) out += "    - " + d + "\n";
    return out;
}

std::string fit_report_json(const FitReport& r) {
    auto figures = [](const SkeletonFigures& f) {
        return nlohmann::json{{"segments", f.segments},
                              {"total_length", f.total_length},
                              {"height", f.height},
                              {"crown_width", f.crown_width},
                              {"per_depth", f.per_depth}};
    };
    nlohmann::json doc{
        {"format", "sylva-infer-report"},
        {"version", 1},
        {"rules", r.rules},
        {"modules", r.modules},
        {"max_rules", r.max_rules},
        {"within_rule_limit", r.within_rule_limit},
        {"segments_per_step", r.segments_per_step},
        {"example", figures(r.example)},
        {"regrown", figures(r.regrown)},
        {"hausdorff", r.hausdorff},
        {"hausdorff_over_height", r.example.height > 0.0 ? r.hausdorff / r.example.height : 0.0},
        {"generalised", r.generalised},
        {"dropped", r.dropped}};
    return doc.dump(1) + "\n";
}

}  // namespace sylva
