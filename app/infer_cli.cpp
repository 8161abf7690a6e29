#include "app/infer_cli.h"

#include <chrono>
#include <optional>
#include <string>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "infer/fit_report.h"
#include "infer/rule_inference.h"

namespace sylva {
namespace {

constexpr const char* kInferHelp = R"(
  sylva infer    -t SKELETON -o TEMPLATE.toml [--report REPORT.json] [--up y|z]
                 [--name NAME] [--max-rules N] [--no-fit]
                 SKELETON: skeleton.json, a cylinder table (CSV/TXT, TreeQSM's columns
                 or named ones) or an OBJ of line segments; --up says which axis of a
                 CSV or OBJ points up (CSV: z, OBJ: y). Writes a template whose rules
                 regrow the tree and prints how close it comes (docs/infer.md).
)";

struct InferOptions {
    std::string input, output, report, name = "inferred";
    std::optional<UpAxis> up;
    int max_rules = 12;
    bool fit = true;
};

void write_text(const std::string& path, const std::string& text) {
    write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace

void print_infer_help(std::FILE* to) {
    std::fputs(kInferHelp, to);
}

int run_infer_command(int argc, char** argv) {
    InferOptions o;
    auto usage = [](const std::string& what) {
        std::fprintf(stderr, "sylva infer: %s\n(see sylva infer --help)\n", what.c_str());
        return 2;
    };
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::optional<std::string> {
            if (i + 1 >= argc) return std::nullopt;
            return std::string(argv[++i]);
        };
        if (arg == "--help" || arg == "-h") {
            std::fputs("Usage:", stdout);
            print_infer_help(stdout);
            return 0;
        }
        if (arg == "--no-fit") {
            o.fit = false;
            continue;
        }
        std::optional<std::string> v = value();
        if (!v) return usage(arg + " needs a value");
        if (arg == "-t") {
            o.input = *v;
        } else if (arg == "-o") {
            o.output = *v;
        } else if (arg == "--report") {
            o.report = *v;
        } else if (arg == "--name") {
            o.name = *v;
        } else if (arg == "--up") {
            if (*v == "y" || *v == "Y")
                o.up = UpAxis::Y;
            else if (*v == "z" || *v == "Z")
                o.up = UpAxis::Z;
            else
                return usage("--up takes y or z, not '" + *v + "'");
        } else if (arg == "--max-rules") {
            try {
                std::size_t used = 0;
                o.max_rules = std::stoi(*v, &used);
                if (used != v->size() || o.max_rules < 1 || o.max_rules > 100) throw 0;
            } catch (...) {
                return usage("--max-rules takes a whole number from 1 to 100");
            }
        } else {
            return usage("unknown option '" + arg + "'");
        }
    }
    if (o.input.empty()) return usage("infer needs -t SKELETON");
    if (o.output.empty()) return usage("infer needs -o TEMPLATE.toml");

    const auto start = std::chrono::steady_clock::now();
    const ExampleTree example = read_example_tree(o.input, o.up);
    InferSettings settings;
    settings.max_rules = o.max_rules;
    settings.name = o.name;
    const InferredTemplate inferred = infer_template(example, settings);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    write_text(o.output, inferred.text);
    std::printf("wrote %s: %d rules from %zu segments (%s), inferred in %.1f ms\n",
                o.output.c_str(), inferred.rules, example.skeleton.segments.size(),
                example.format.c_str(), ms);
    if (!inferred.within_rule_limit)
        std::printf("  the tree needs more than %d rules: the grammar has %d\n", o.max_rules,
                    inferred.rules);
    if (!o.fit && o.report.empty()) return 0;
    FitReport report = fit_report(example, inferred);
    report.max_rules = o.max_rules;
    std::fputs(fit_report_text(report).c_str(), stdout);
    if (!o.report.empty()) {
        write_text(o.report, fit_report_json(report));
        std::printf("wrote %s\n", o.report.c_str());
    }
    return 0;
}

}  // namespace sylva
