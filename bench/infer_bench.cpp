// sylva-bench-infer: rules from an example tree (infer/, docs/infer.md) against the targets
// of the inference: for every built-in template and 5 random parameter sets (the #define
// sliders drawn in their ranges, a random seed), skeleton -> infer -> regrow; prints each
// figure's error and whether it meets its target, then the time to infer a tree of about
// 10,000 segments. Prints figures from one run; asserts nothing.
//
//   build/bench/sylva-bench-infer [--markdown] [--summary] [--dump DIR] [SETS] [TEMPLATE...]
//
// After the line per run, how many runs of each template meet every target (plain and
// jittered), then how many runs meet each target. --summary leaves out the line per run; --dump
// writes each run's inferred template to DIR/TEMPLATE-SET-KIND.toml, to read why a run misses.
// --natural adds, per run, a line "seed+1": the same figures between the original and the
// original grown from the next seed (no inference), i.e. how far the template's own
// variation is from each target; where it misses, a stochastic grammar that matches the
// template's statistics misses too.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <regex>
#include <string>
#include <vector>

#include "bench/common.h"
#include "core/random.h"
#include "infer/fit_report.h"
#include "infer/rule_inference.h"
#include "infer/skeleton_figures.h"
#include "tree/growth.h"
#include "tree/template_library.h"
#include "turtle/lsystem_params.h"

namespace {

using namespace sylva;

// Draws every "#define NAME VALUE # [lo, hi]" of the grammar within its range.
std::string randomized_grammar(const std::string& grammar, Random& random) {
    static const std::regex line(
        R"((#define\s+\w+\s+)([-+0-9.eE]+)(\s*#\s*\[\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\].*))");
    std::string out;
    std::size_t at = 0;
    while (at < grammar.size()) {
        std::size_t end = grammar.find('\n', at);
        if (end == std::string::npos) end = grammar.size();
        std::string text = grammar.substr(at, end - at);
        std::smatch m;
        if (std::regex_match(text, m, line)) {
            const double lo = std::stod(m[4]), hi = std::stod(m[5]);
            const bool whole = m[2].str().find('.') == std::string::npos && lo == std::floor(lo) &&
                               hi == std::floor(hi) && hi - lo < 30;
            double v = lo + (hi - lo) * random.uniform();
            if (whole) v = std::round(v);
            char number[32];
            std::snprintf(number, sizeof number, "%.4g", v);
            text = m[1].str() + number + m[3].str();
        }
        out += text;
        if (end < grammar.size()) out += '\n';
        at = end + 1;
    }
    return out;
}

bool deterministic(const TreeTemplate& t) {
    return t.growth == "lsystem" && t.grammar.find("rand(") == std::string::npos &&
           t.grammar.find(" : 0.") == std::string::npos && lsystem_params(t.params).jitter == 0.0 &&
           lsystem_params(t.params).bend == 0.0 &&
           lsystem_params(t.params).width_variation == 0.0 && t.params.tropism_variation == 0.0;
}

ExampleTree as_example(const Skeleton& skeleton, const TreeParams& params) {
    ExampleTree e;
    e.skeleton = skeleton;
    e.params = params;
    e.format = "skeleton.json";
    finish_example_tree(e, "bench");
    return e;
}

struct Tally {
    int all = 0;  // runs that meet every target (and the exact regrowth, where it applies)
    int runs = 0, count = 0, length = 0, height = 0, width = 0, depth = 0, hausdorff = 0, rules = 0,
        exact = 0, exact_runs = 0;
};

// Counts the run in `t` and adds its line to `runs`; returns whether it meets every target.
bool row(const char* name, int set, const char* kind, const FitReport& r, double natural,
         bool exact_case, Tally& t, bench::Table& runs) {
    const double dc = relative_difference(double(r.example.segments), double(r.regrown.segments));
    const double dl = relative_difference(r.example.total_length, r.regrown.total_length);
    const double dh = relative_difference(r.example.height, r.regrown.height);
    const double dw = relative_difference(r.example.crown_width, r.regrown.crown_width);
    double dd = 0.0;
    const std::size_t depths = std::max(r.example.per_depth.size(), r.regrown.per_depth.size());
    for (std::size_t d = 0; d < depths; ++d) {
        const double a = d < r.example.per_depth.size() ? double(r.example.per_depth[d]) : 0.0;
        const double b = d < r.regrown.per_depth.size() ? double(r.regrown.per_depth[d]) : 0.0;
        dd = std::max(dd, relative_difference(a, b));
    }
    const bool ok_h = exact_case ? r.hausdorff <= 0.01 * r.example.height : r.hausdorff <= natural;
    ++t.runs;
    t.count += dc <= 0.1;
    t.length += dl <= 0.1;
    t.height += dh <= 0.05;
    t.width += dw <= 0.05;
    t.depth += dd <= 0.1;
    t.hausdorff += ok_h;
    t.rules += r.rules <= 12;
    bool exact = true;
    if (exact_case) {
        ++t.exact_runs;
        exact = r.hausdorff <= 0.01 * r.example.height && r.example.segments == r.regrown.segments;
        t.exact += exact;
    }
    const bool all = dc <= 0.1 && dl <= 0.1 && dh <= 0.05 && dw <= 0.05 && dd <= 0.1 && ok_h &&
                     r.rules <= 12 && exact;
    t.all += all;
    auto* f = &bench::format;
    runs.row({name, std::to_string(set), kind, std::to_string(r.example.segments),
              f("%.1f%%", 100 * dc), f("%.1f%%", 100 * dl), f("%.1f%%", 100 * dh),
              f("%.1f%%", 100 * dw), f("%.1f%%", 100 * dd),
              f("%.3f%s", r.hausdorff, ok_h ? "" : " !"),
              f("%.3f", exact_case ? 0.01 * r.example.height : natural), std::to_string(r.rules)});
    return all;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    const bool markdown = bench::take_flag(args, "--markdown");
    const bool summary = bench::take_flag(args, "--summary");
    const bool natural_rows = bench::take_flag(args, "--natural");
    std::string dump;
    if (args.size() >= 2 && args[0] == "--dump") {
        dump = args[1];
        args.erase(args.begin(), args.begin() + 2);
    }
    const int sets = !args.empty() ? std::max(1, std::atoi(args[0].c_str())) : 5;
    std::vector<std::string> only(args.begin() + std::min<std::size_t>(args.size(), 1), args.end());
    auto save = [&](const std::string& name, int set, const char* kind,
                    const InferredTemplate& inferred) {
        if (dump.empty()) return;
        const std::string path =
            dump + "/" + name + "-" + std::to_string(set) + "-" + kind + ".toml";
        if (std::FILE* f = std::fopen(path.c_str(), "w")) {
            std::fputs(inferred.text.c_str(), f);
            std::fclose(f);
        }
    };
    bench::Table runs({"template", "set", "kind", "segs", "count", "length", "height", "width",
                       "depth", "hausdorff", "limit", "rules"});
    Tally t;
    bench::Table per_template({"template", "plain: every target", "jittered: every target"});
    for (const TreeTemplate* base : builtin_templates()) {
        if (!only.empty() && std::find(only.begin(), only.end(), base->name) == only.end())
            continue;
        int plain_all = 0, jitter_all = 0, sets_run = 0;
        for (int set = 0; set < sets; ++set) {
            Random random(0x5eed0000u + static_cast<std::uint64_t>(set) * 7919u +
                          std::hash<std::string>{}(base->name));
            TreeTemplate tree = *base;
            if (set > 0) {
                tree.grammar = randomized_grammar(tree.grammar, random);
                tree.params.seed = 1 + (random.next() % 100000);
            }
            const Skeleton skeleton = grow(tree);
            if (skeleton.segments.empty()) continue;
            TreeTemplate other = tree;
            other.params.seed = tree.params.seed + 1;
            const bool exact_case = deterministic(tree);
            const double natural = skeleton_hausdorff(skeleton, grow(other));
            const ExampleTree example = as_example(skeleton, tree.params);
            if (natural_rows) {
                FitReport twin;
                twin.example = skeleton_figures(skeleton);
                twin.regrown = skeleton_figures(grow(other));
                twin.hausdorff = natural;
                Tally ignored;
                row(base->name.c_str(), set, "seed+1", twin, natural, false, ignored, runs);
            }
            const InferredTemplate inferred = infer_template(example);
            save(base->name, set, "plain", inferred);
            ++sets_run;
            plain_all += row(base->name.c_str(), set, "plain", fit_report(example, inferred),
                             natural, exact_case, t, runs);
            const ExampleTree noisy = as_example(jittered(skeleton, 77 + set), tree.params);
            const InferredTemplate inferred_noisy = infer_template(noisy);
            save(base->name, set, "jitter", inferred_noisy);
            jitter_all += row(base->name.c_str(), set, "jitter", fit_report(noisy, inferred_noisy),
                              natural, exact_case, t, runs);
        }
        const std::string of = "/" + std::to_string(sets_run);
        per_template.row(
            {base->name, std::to_string(plain_all) + of, std::to_string(jitter_all) + of});
    }
    if (!summary) {
        runs.print(markdown);
        std::printf("\n");
    }
    per_template.print(markdown);
    std::printf("\n");
    bench::Table targets({"target", "runs that meet it", "of"});
    const std::string of = std::to_string(t.runs);
    targets.row({"segment count within 10%", std::to_string(t.count), of});
    targets.row({"total length within 10%", std::to_string(t.length), of});
    targets.row({"height within 5%", std::to_string(t.height), of});
    targets.row({"crown width within 5%", std::to_string(t.width), of});
    targets.row({"segments per depth within 10%", std::to_string(t.depth), of});
    targets.row({"Hausdorff distance within its limit", std::to_string(t.hausdorff), of});
    targets.row({"at most 12 rules", std::to_string(t.rules), of});
    targets.row({"deterministic templates regrown exactly", std::to_string(t.exact),
                 std::to_string(t.exact_runs)});
    targets.row({"every target", std::to_string(t.all), of});
    targets.print(markdown);
    std::printf("\n");

    // Speed: honda at 14 generations has 16,383 segments.
    TreeTemplate big = *builtin_templates().front();
    for (const TreeTemplate* b : builtin_templates())
        if (b->name == "honda") big = *b;
    big.params.blocks.edit<LSystemParams>().generations = 14;
    const Skeleton skeleton = grow(big);
    const ExampleTree example = as_example(skeleton, big.params);
    const bench::Times best = bench::best_of(5, [&] { (void)infer_template(example); });
    std::printf("infer %zu segments (honda, 14 generations): %.1f ms (best of 5; target 1000 ms)\n",
                skeleton.segments.size(), best.wall_ms);
    return 0;
}
