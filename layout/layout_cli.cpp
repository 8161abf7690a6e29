#include "layout/layout_cli.h"

#include <chrono>
#include <filesystem>
#include <optional>
#include <system_error>
#include <type_traits>
#include <vector>

#include "core/errors.h"
#include "core/file_set.h"
#include "core/input_file.h"
#include "core/output_folder.h"
#include "core/seed.h"
#include "layout/graph_grammar.h"
#include "layout/positions.h"

namespace sylva::layout {

PolygonMesh load_example(const std::string& name_or_path) {
    for (const auto& [name, text] : builtin_examples())
        if (name == name_or_path) return read_mesh_text(text, name + ".mesh");
    if (!std::filesystem::exists(name_or_path))
        throw InputError("'" + name_or_path +
                         "' is neither a shipped example (see 'sylva layout examples') nor a file");
    return read_mesh_file(name_or_path);
}

namespace {

std::string read_text(const std::string& path) {
    return read_input_file(path, "layout grammar");
}

bool is_grammar_file(const std::string& path) {
    if (std::filesystem::path(path).extension() != ".json" || !std::filesystem::exists(path))
        return false;
    return read_text(path).find("\"sylva-layout-grammar\"") != std::string::npos;
}

// A flag's whole number in lo..hi, or nothing: a bad value is a usage error (exit 2), as
// every other flag's.
std::optional<long long> parse_int(const std::string& value, long long lo, long long hi) {
    std::size_t used = 0;
    long long v = 0;
    try {
        v = std::stoll(value, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (value.empty() || used != value.size() || v < lo || v > hi) return std::nullopt;
    return v;
}

}  // namespace

int run_layout_cli(const std::vector<std::string>& args, std::FILE* out, std::FILE* err) {
    const char* const synopsis =
        "usage: sylva layout examples\n"
        "       sylva layout derive EXAMPLE [--max-graphs N] [--max-vertices N] -o grammar.json\n"
        "       sylva layout generate EXAMPLE|GRAMMAR [--count N] [--seed S] [--steps K] -o DIR/\n"
        "(docs/layout.md)\n";
    auto usage = [&](const std::string& why) {
        std::fprintf(err, "sylva: %s\n%s", why.c_str(), synopsis);
        return 2;
    };
    // Sets `*to` from the flag's value; false (after printing why) when it is not a whole
    // number in lo..hi.
    auto whole = [&](const std::string& flag, const std::string& value, long long lo, long long hi,
                     auto* to) {
        const std::optional<long long> v = parse_int(value, lo, hi);
        if (!v) {
            usage(flag + " expects a whole number from " + std::to_string(lo) + " to " +
                  std::to_string(hi) + ", not '" + value + "'");
            return false;
        }
        *to = static_cast<std::remove_pointer_t<decltype(to)>>(*v);
        return true;
    };
    for (const std::string& a : args)
        if (a == "--help" || a == "-h") {
            std::fputs(synopsis, out);
            return 0;
        }
    if (args.size() < 2) return usage("layout needs a subcommand");
    const std::string& sub = args[1];
    if (sub == "examples") {
        for (const auto& [name, text] : builtin_examples()) {
            const Example ex = make_example(read_mesh_text(text, name));
            std::fprintf(out, "%s\t%zu polygons, %zu vertices\n", name.c_str(),
                         ex.mesh.polygons.size(), ex.graph.vertices.size());
        }
        return 0;
    }
    std::string input, output;
    long long count = 8, steps = 16;
    DeriveSettings derive;
    std::uint64_t seed = 1;
    for (std::size_t i = 2; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> const std::string* {
            return i + 1 < args.size() ? &args[++i] : nullptr;
        };
        if (a == "-o" || a == "--output") {
            const std::string* v = value();
            if (!v) return usage(a + " needs a value");
            output = *v;
        } else if (a == "--count") {
            const std::string* v = value();
            if (!v) return usage(a + " needs a value");
            if (!whole(a, *v, 1, 10000, &count)) return 2;
        } else if (a == "--seed") {
            const std::string* v = value();
            if (!v) return usage(a + " needs a value");
            if (!whole(a, *v, 0, static_cast<long long>(kMaxSeed), &seed)) return 2;
        } else if (a == "--steps") {
            const std::string* v = value();
            if (!v) return usage(a + " needs a value");
            if (!whole(a, *v, 0, 1000, &steps)) return 2;
        } else if (a == "--max-graphs" || a == "--max-vertices") {
            const std::string* v = value();
            if (!v) return usage(a + " needs a value");
            if (!whole(a, *v, 1, 1000000,
                       a == "--max-graphs" ? &derive.max_graphs : &derive.max_vertices))
                return 2;
        } else if (!a.empty() && a[0] == '-') {
            return usage("unknown option '" + a + "'");
        } else if (input.empty()) {
            input = a;
        } else {
            return usage("unexpected argument '" + a + "'");
        }
    }
    if (input.empty()) return usage("layout " + sub + " needs an EXAMPLE");
    if (output.empty()) return usage("layout " + sub + " needs -o");
    if (sub == "derive") {
        output_target(output);  // a folder or device at -o is refused before the work
        const auto start = std::chrono::steady_clock::now();
        const Grammar grammar = derive_grammar(make_example(load_example(input)), derive);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        FileSet files;
        files.add(output, [&](std::ostream& o) { o << write_grammar_json(grammar); });
        files.commit();
        std::fprintf(out,
                     "wrote %s: %zu primitives, %zu starter rules, %zu rules (hierarchy %d graphs, "
                     "%d open) in %.0f ms\n",
                     output.c_str(), grammar.primitives.size(), grammar.starters.size(),
                     grammar.rules.size(), grammar.hierarchy_graphs, grammar.open_graphs, ms);
        return 0;
    }
    if (sub == "generate") {
        const std::filesystem::path dir(output);
        OutputFolder folder(dir);
        const Grammar grammar = is_grammar_file(input)
                                    ? read_grammar_json(read_text(input), input)
                                    : derive_grammar(make_example(load_example(input)), derive);
        GenerateSettings settings;
        settings.steps = static_cast<int>(steps);
        const std::vector<PolygonMesh> layouts =
            generate_layouts(grammar, static_cast<int>(count), seed, settings);
        FileSet files;
        for (std::size_t i = 0; i < layouts.size(); ++i) {
            char name[32];
            std::snprintf(name, sizeof name, "layout_%03zu", i);
            files.add(dir / (std::string(name) + ".json"),
                      [&](std::ostream& o) { o << write_mesh_json(layouts[i]); });
            files.add(dir / (std::string(name) + ".svg"),
                      [&](std::ostream& o) { o << write_mesh_svg(layouts[i]); });
        }
        files.commit();
        folder.keep();
        std::fprintf(out, "wrote %zu layouts to %s\n", layouts.size(), output.c_str());
        return 0;
    }
    return usage("unknown layout subcommand '" + sub + "'");
}

}  // namespace sylva::layout
