#include "app/layout_cli.h"

#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>

#include "core/errors.h"
#include "core/file_set.h"
#include "core/input_file.h"
#include "core/output_folder.h"
#include "core/seed.h"
#include "layout/contact_sheet.h"
#include "layout/cost.h"
#include "layout/derive.h"
#include "layout/examples.h"
#include "layout/grammar_json.h"
#include "layout/variations.h"
#include "tree/cost.h"

namespace sylva {

namespace {

constexpr const char* kLayoutHelp = R"(usage: sylva layout examples
       sylva layout derive EXAMPLE [derive flags] [limits] -o grammar.json
       sylva layout generate EXAMPLE|GRAMMAR [--count N] [--seed S] [--size N | --size A..B |
                 --area A] [--length CLASS=LO..HI]... [--max-steps N] [--max-layout-vertices N]
                 [--threads N] [--sheet FILE.svg] [derive flags] [limits] -o DIR/
  EXAMPLE: a shipped example (sylva layout examples) or a .mesh / .json file; GRAMMAR: a
  file `derive` wrote.
  derive:   the graph grammar of the example, as JSON; says which limit ended the hierarchy.
  generate: N variations (default 8) as DIR/layout_NNN.json (with planting classes, for
            sylva forest --layout) and .svg; --sheet also writes one picture of the
            example and every variation. The same input, seed and flags give the same bytes.
  --size N        each variation grown to N polygons (corners for an example of one
                  polygon); Nx: N times the example's size; A..B (or Ax..Bx) spreads
                  the sizes over A to B; default: from just above the example's size
                  to 12 times it
  --area A        grown to about A square units of the example instead
  --length CLASS=LO..HI
                  edge lengths of a class in LO to HI (LO.. for no upper end): CLASS is a
                  colour pair (meadow/path, forest/outside), one colour (any edge of it) or
                  *; default per edge 0.5 to 3 times the example's mean for its kind
  --max-steps N   rule applications per variation (default 4 x size + 64)
  --max-layout-vertices N
                  refuse moves that would pass N vertices (default: none)
  derive flags (also for generate from an EXAMPLE):
  --max-graphs N  hierarchy graphs to make (default 6000)
  --max-generations N, --max-vertices N (per hierarchy graph), --max-pieces N (per rule
                  side), --derive-seconds S: further limits, none by default
  limits: --max-seconds S, --max-memory MB refuse a job estimated above them (default 10 s,
  2000 MB)
(docs/layout.md)
)";

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

template <class T>
T number(const std::string& flag, const std::string& text, T lo, T hi) {
    T v{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    bool ok = error == std::errc() && end == text.data() + text.size() && !text.empty();
    if constexpr (std::is_floating_point_v<T>) ok = ok && std::isfinite(v);
    if (!ok || v < lo || v > hi) {
        auto shown = [](T x) {
            if constexpr (std::is_floating_point_v<T>) {
                char out[32];
                std::snprintf(out, sizeof out, "%g", x);
                return std::string(out);
            } else {
                return std::to_string(x);
            }
        };
        throw UsageError(flag + " expects a number from " + shown(lo) + " to " + shown(hi) +
                         ", not '" + text + "'");
    }
    return v;
}

bool is_grammar_file(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::path(path).extension() != ".json" ||
        !std::filesystem::is_regular_file(path, ec))
        return false;
    return read_input_file(path, "layout grammar").find("\"sylva-layout-grammar\"") !=
           std::string::npos;
}

std::string figure(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

// Refuses a job above the limits, as tree/cost.h's check_cost does for trees.
void check_layout_cost(const layout::LayoutCost& cost, const CostLimits& limits,
                       const std::string& what) {
    if (cost.bytes <= limits.max_bytes && cost.seconds <= limits.max_seconds) return;
    char text[160];
    std::snprintf(text, sizeof text, "about %.2g GB and %.3g s", cost.bytes / 1e9, cost.seconds);
    char limit[96];
    std::snprintf(limit, sizeof limit, "%.0f MB and %.3g s", limits.max_bytes / 1e6,
                  limits.max_seconds);
    throw InputError(what + " (" + cost.what + ") is estimated at " + text +
                     ", over the limit of " + limit +
                     " (lower --count, --size or --max-graphs, or raise the limits with "
                     "--max-memory MB / --max-seconds S)");
}

std::string derive_summary(const layout::Grammar& g, const layout::DeriveSettings& s) {
    const layout::HierarchyReport& h = g.hierarchy;
    std::string out =
        std::to_string(g.primitives.size()) + " primitives, " + std::to_string(g.starters.size()) +
        " starter rules, " + std::to_string(g.rules.size()) + " rules; hierarchy " +
        std::to_string(h.graphs) + " graphs in " + std::to_string(h.generations) + " generations, ";
    if (h.stopped_by == "closed") {
        out += "closed (the grammar reduces every graph it met)";
    } else {
        const std::string limit =
            h.stopped_by == "graphs"    ? "--max-graphs " + std::to_string(s.max_graphs)
            : h.stopped_by == "seconds" ? "--derive-seconds " + figure(s.max_seconds)
                                        : "--max-generations " + std::to_string(s.max_generations);
        out += std::to_string(h.open_graphs) + " still open: ended by " + limit;
    }
    std::vector<std::string> notes;
    if (h.vertex_limited)
        notes.push_back(std::to_string(h.vertex_limited) + " graphs over --max-vertices");
    if (h.piece_limited)
        notes.push_back(std::to_string(h.piece_limited) + " boundaries over --max-pieces");
    if (h.decompositions_cut)
        notes.push_back(std::to_string(h.decompositions_cut) + " decompositions cut short");
    if (h.multi_boundary)
        notes.push_back(std::to_string(h.multi_boundary) + " graphs with several open boundaries");
    if (h.example_added) notes.push_back("the example added as a starter");
    for (const std::string& n : notes) out += "; " + n;
    return out;
}

}  // namespace

void print_layout_help(std::FILE* to) {
    std::fputs(kLayoutHelp, to);
}

int run_layout_cli(const std::vector<std::string>& args, std::FILE* out, std::FILE* err) {
    for (const std::string& a : args)
        if (a == "--help" || a == "-h") {
            print_layout_help(out);
            return 0;
        }
    try {
        if (args.size() < 2) throw UsageError("layout needs a subcommand");
        const std::string& sub = args[1];
        if (sub == "examples") {
            if (args.size() > 2) throw UsageError("unexpected argument '" + args[2] + "'");
            for (const auto& [name, text] : layout::builtin_examples()) {
                const layout::Example ex = layout::make_example(layout::read_mesh_text(text, name));
                std::fprintf(out, "%s\t%zu polygons, %zu vertices\n", name.c_str(),
                             ex.mesh.polygons.size(), ex.graph.vertices.size());
            }
            return 0;
        }
        if (sub != "derive" && sub != "generate")
            throw UsageError("unknown layout subcommand '" + sub + "'");
        std::string input, output, sheet;
        int count = 8;
        std::uint64_t seed = 1;
        layout::DeriveSettings derive;
        layout::VariationSettings vary;
        CostLimits limits;
        std::vector<std::pair<std::string, layout::LengthRange>> lengths;
        std::string size_spec;  // resolved once the example's size is known
        for (std::size_t i = 2; i < args.size(); ++i) {
            const std::string& a = args[i];
            auto value = [&]() -> const std::string& {
                if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
                return args[++i];
            };
            const bool generate = sub == "generate";
            auto generate_only = [&] {
                if (!generate) throw UsageError(a + " applies to layout generate only");
            };
            if (a == "-o" || a == "--output") {
                output = value();
            } else if (a == "--count") {
                generate_only();
                count = number<int>(a, value(), 1, 100000);
            } else if (a == "--seed") {
                generate_only();
                seed = number<std::uint64_t>(a, value(), 0, kMaxSeed);  // core/seed.h
            } else if (a == "--size") {
                generate_only();
                size_spec = value();
            } else if (a == "--area") {
                generate_only();
                vary.area = number<double>(a, value(), 1e-9, 1e15);
            } else if (a == "--length") {
                generate_only();
                const std::string v = value();
                const std::size_t eq = v.rfind('=');
                const std::size_t dots = v.find("..", eq == std::string::npos ? 0 : eq);
                if (eq == std::string::npos || eq == 0 || dots == std::string::npos)
                    throw UsageError("--length expects CLASS=LO..HI, not '" + v + "'");
                layout::LengthRange r;
                r.lo = number<double>(a, v.substr(eq + 1, dots - eq - 1), 0.0, 1e8);
                if (dots + 2 < v.size()) r.hi = number<double>(a, v.substr(dots + 2), 1e-9, 1e8);
                if (r.hi > 0 && r.hi < r.lo)
                    throw UsageError("--length needs LO <= HI, not '" + v + "'");
                lengths.emplace_back(v.substr(0, eq), r);
            } else if (a == "--max-steps") {
                generate_only();
                vary.grow.max_steps = number<int>(a, value(), 1, 100000000);
            } else if (a == "--max-layout-vertices") {
                generate_only();
                vary.grow.max_vertices = number<int>(a, value(), 1, 100000000);
            } else if (a == "--threads") {
                generate_only();
                vary.threads = number<int>(a, value(), 1, 1024);
            } else if (a == "--sheet") {
                generate_only();
                sheet = value();
            } else if (a == "--max-graphs") {
                derive.max_graphs = number<int>(a, value(), 1, 100000000);
            } else if (a == "--max-generations") {
                derive.max_generations = number<int>(a, value(), 1, 100000000);
            } else if (a == "--max-vertices") {
                derive.max_vertices = number<int>(a, value(), 1, 100000000);
            } else if (a == "--max-pieces") {
                derive.max_pieces = number<int>(a, value(), 1, 100000000);
            } else if (a == "--derive-seconds") {
                derive.max_seconds = number<double>(a, value(), 1e-3, 1e7);
            } else if (a == "--max-seconds") {
                limits.max_seconds =
                    static_cast<double>(number<std::uint64_t>(a, value(), 1, 1ULL << 40));
            } else if (a == "--max-memory") {
                limits.max_bytes =
                    1e6 * static_cast<double>(number<std::uint64_t>(a, value(), 1, 1ULL << 40));
            } else if (!a.empty() && a[0] == '-') {
                throw UsageError("unknown option '" + a + "'");
            } else if (input.empty()) {
                input = a;
            } else {
                throw UsageError("unexpected argument '" + a + "'");
            }
        }
        if (input.empty()) throw UsageError("layout " + sub + " needs an EXAMPLE");
        if (output.empty() && (sub == "derive" || sheet.empty()))
            throw UsageError("layout " + sub + " needs -o");
        if (!size_spec.empty() && vary.area > 0) throw UsageError("--size and --area: give one");
        // N, A..B, Nx or Ax..Bx (x: times the example's size); checked before any work.
        struct SizeSpec {
            double low = 0, high = 0;
            bool relative = false;
        } spec;
        if (!size_spec.empty()) {
            const std::size_t dots = size_spec.find("..");
            auto part = [&](std::string t, bool& relative) {
                relative = !t.empty() && t.back() == 'x';
                if (relative) t.pop_back();
                return relative ? number<double>("--size", t, 1e-3, 1e6)
                                : static_cast<double>(number<int>("--size", t, 1, 1000000));
            };
            bool r1 = false, r2 = false;
            spec.low = part(size_spec.substr(0, dots), r1);
            spec.high = dots == std::string::npos ? spec.low : part(size_spec.substr(dots + 2), r2);
            if (dots != std::string::npos && r1 != r2)
                throw UsageError("--size A..B: both absolute or both with x, not '" + size_spec +
                                 "'");
            if (spec.high < spec.low)
                throw UsageError("--size A..B needs A <= B, not '" + size_spec + "'");
            spec.relative = r1;
        }

        if (sub == "derive") {
            output_target(output);  // a folder or device at -o is refused before the work
            const layout::Example ex = layout::make_example(layout::load_example(input));
            check_layout_cost(layout::derive_cost(ex, derive), limits, "deriving " + input);
            const auto start = std::chrono::steady_clock::now();
            const layout::Grammar grammar = layout::derive_grammar(ex, derive);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            FileSet files;
            files.add(output, [&](std::ostream& o) { o << layout::write_grammar_json(grammar); });
            files.commit();
            std::fprintf(out, "wrote %s: %s (%.0f ms)\n", output.c_str(),
                         derive_summary(grammar, derive).c_str(), ms);
            return 0;
        }

        // generate
        const std::filesystem::path dir(output);
        std::optional<OutputFolder> folder;
        if (!output.empty()) folder.emplace(dir);
        if (!sheet.empty()) output_target(sheet);
        std::optional<layout::Example> example;
        layout::Grammar grammar;
        if (is_grammar_file(input)) {
            grammar = layout::read_grammar_json(read_input_file(input, "layout grammar"), input);
        } else {
            example = layout::make_example(layout::load_example(input));
            check_layout_cost(layout::derive_cost(*example, derive), limits, "deriving " + input);
            grammar = layout::derive_grammar(*example, derive);
            std::fprintf(out, "grammar: %s\n", derive_summary(grammar, derive).c_str());
        }
        const std::vector<std::string> classes = layout::edge_classes(grammar.dirs);
        for (const auto& [cls, range] : lengths) {
            if (cls != "*" && !std::count(classes.begin(), classes.end(), cls)) {
                std::string known;
                for (const std::string& c : classes) known += (known.empty() ? "" : ", ") + c;
                throw InputError("--length: no edge class '" + cls + "' in " + input +
                                 " (its classes: " + known + ", *)");
            }
            vary.lengths.ranges[cls] = range;
        }
        const layout::GrowthTable table(grammar);
        if (!size_spec.empty()) {
            const double unit = spec.relative ? table.example_size() : 1.0;
            const int low = std::max(1, static_cast<int>(std::lround(spec.low * unit)));
            const int high = std::max(low, static_cast<int>(std::lround(spec.high * unit)));
            if (low == high)
                vary.size = low;
            else
                vary.spread_low = low, vary.spread_high = high;
        }
        check_layout_cost(layout::generate_cost(table, count, vary), limits,
                          "generating from " + input);
        layout::VariationsReport report;
        const std::vector<layout::PolygonMesh> layouts =
            layout::generate_layouts(table, count, seed, vary, &report);
        FileSet files;
        if (!output.empty())
            for (std::size_t i = 0; i < layouts.size(); ++i) {
                char name[32];
                std::snprintf(name, sizeof name, "layout_%03zu", i);
                files.add(dir / (std::string(name) + ".json"),
                          [&](std::ostream& o) { o << layout::write_mesh_json(layouts[i]); });
                files.add(dir / (std::string(name) + ".svg"),
                          [&](std::ostream& o) { o << layout::write_mesh_svg(layouts[i]); });
            }
        if (!sheet.empty()) {
            std::vector<layout::SheetItem> items;
            const char* unit = layout::measure_name(report.measure);
            if (example) items.push_back({&example->mesh, "example"});
            for (std::size_t i = 0; i < layouts.size(); ++i) {
                const int size = report.items[i].size;
                items.push_back(
                    {&layouts[i], std::to_string(i) + ": " + std::to_string(size) + " " + unit});
            }
            files.add(sheet, [&](std::ostream& o) { o << layout::write_sheet_svg(items); });
        }
        files.commit();
        if (folder) folder->keep();
        int lo = 1 << 30, hi = 0, tlo = 1 << 30, thi = 0;
        for (const layout::VariationReport& r : report.items) {
            lo = std::min(lo, r.size), hi = std::max(hi, r.size);
            tlo = std::min(tlo, r.target), thi = std::max(thi, r.target);
        }
        const char* unit = layout::measure_name(report.measure);
        std::fprintf(out, "wrote %zu layouts%s%s%s%s: %d to %d %s (targets %d to %d)\n",
                     layouts.size(), output.empty() ? "" : " to ", output.c_str(),
                     sheet.empty() ? "" : " and the sheet ", sheet.c_str(), lo, hi, unit, tlo, thi);
        const std::string bound = report.limits();
        if (!bound.empty()) std::fprintf(out, "limits: %s\n", bound.c_str());
        return 0;
    } catch (const UsageError& e) {
        std::fprintf(err, "sylva: %s\n", e.what());
        print_layout_help(err);
        return 2;
    }
}

}  // namespace sylva
