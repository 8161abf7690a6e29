// sylva: the headless command-line interface (SPEC section 8).
// Exit codes: 0 ok, 2 usage, 3 invalid input, 4 I/O error.
#include "app/errors.h"
#include "app/export.h"
#include "app/lowpoly_tree.h"
#include "app/pipeline.h"
#include "app/skeleton_json.h"
#include "app/template_library.h"
#include "marching/mesh_checks.h"
#include "turtle/grammar_error.h"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace sylva;

constexpr int kOk = 0, kUsage = 2, kInvalidInput = 3, kIoError = 4;
// Beyond the 15 generations of a tree, grammar experiments (ABOP Fig. 1.31a takes 30 steps)
// may ask for more; growing words stop at the module cap long before this.
constexpr int kMaxSteps = 1000;

constexpr const char* kHelp = R"(sylva: low-poly trees from L-systems

Usage:
  sylva export   [-t NAME|FILE] [--set KEY=VALUE]... [--seed N] [--budget N] [--lod]
                 [--mesher KIND] -o OUT.{obj,glb,ply}
  sylva derive   [-t NAME|FILE] [--steps N] [--seed N]
  sylva skeleton [-t NAME|FILE] [--set KEY=VALUE]... [--seed N] -o skeleton.json
  sylva templates
  sylva --help

  -t NAME|FILE     a built-in template (see `sylva templates`) or a grammar file;
                   default: the built-in default tree
  --set KEY=VALUE  override a parameter (keys below); may be repeated
  --seed N         seed of stochastic rules and rand() (default 1)
  --steps N        derivation steps (default: the template's generations)
  --mesher KIND    sparse (default: skips empty space), dense (every grid node), or vdb
                   (OpenVDB narrow band + volumeToMesh)
  --adaptivity A   vdb mesher only: 0 (uniform, default) to 1 (merge flat regions)
  --budget N       trunk + crown reduced to N triangles (quadric decimation, stays closed);
                   0 keeps every triangle; default: the template's triangle_budget (800)
  --budget-trunk N, --budget-crown N
                   a budget per part instead
  --lod            LOD0-LOD3 with budgets N, N/2, N/4, N/8: one .glb with a node per level,
                   or OUT_LOD0.obj ... (names game engines pick up)
  --format F       obj, glb or ply (default: from the extension of OUT)
  --shading S      flat (default, faceted) or smooth normals
  --ply-ascii      write PLY as text instead of binary
  --fidelity       also report the distance of the reduced trunk + crown to the
                   resolution-200 surface, in percent of the tree's height
  -o PATH          output file; written to a temporary file, then renamed

Exit codes: 0 ok, 2 usage, 3 invalid input, 4 I/O error.

Parameters:
)";

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Options {
    std::string command;
    std::string tree = "default";
    std::vector<std::pair<std::string, std::string>> sets;
    std::optional<std::uint64_t> seed;
    std::optional<int> steps;
    std::string output;
    MeshOptions mesh;
    std::optional<std::size_t> budget, budget_trunk, budget_crown;
    bool lod = false;
    bool fidelity = false;
    std::optional<ExportFormat> format;
    ExportOptions export_options;
};

template <class T>
T parse_integer(const std::string& flag, const std::string& text) {
    T value{};
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
        throw UsageError(flag + " expects a whole number, not '" + text + "'");
    return value;
}

Options parse_options(int argc, char** argv) {
    Options o;
    if (argc < 2) throw UsageError("missing command");
    o.command = argv[1];
    for (int i = 2; i < argc; ++i) {
        std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw UsageError(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "-t" || arg == "--template") {
            o.tree = value();
        } else if (arg == "--set") {
            std::string kv = value();
            size_t eq = kv.find('=');
            if (eq == std::string::npos) throw UsageError("--set expects KEY=VALUE, not '" + kv + "'");
            o.sets.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
        } else if (arg == "--seed") {
            o.seed = parse_integer<std::uint64_t>(arg, value());
        } else if (arg == "--steps") {
            o.steps = parse_integer<int>(arg, value());
            if (*o.steps < 0 || *o.steps > kMaxSteps)
                throw UsageError("--steps must be 0 to " + std::to_string(kMaxSteps));
        } else if (arg == "--mesher") {
            std::string name = value();
            std::optional<Mesher> mesher = mesher_from_name(name);
            if (!mesher) throw UsageError("--mesher expects dense, sparse or vdb, not '" + name + "'");
            o.mesh.mesher = *mesher;
        } else if (arg == "--adaptivity") {
            std::string text = value();
            double a = -1.0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), a);
            if (error != std::errc() || end != text.data() + text.size() || !(a >= 0.0 && a <= 1.0))
                throw UsageError("--adaptivity expects a number from 0 to 1, not '" + text + "'");
            o.mesh.vdb_adaptivity = a;
        } else if (arg == "--budget") {
            o.budget = parse_integer<std::size_t>(arg, value());
        } else if (arg == "--budget-trunk") {
            o.budget_trunk = parse_integer<std::size_t>(arg, value());
        } else if (arg == "--budget-crown") {
            o.budget_crown = parse_integer<std::size_t>(arg, value());
        } else if (arg == "--lod") {
            o.lod = true;
        } else if (arg == "--fidelity") {
            o.fidelity = true;
        } else if (arg == "--format") {
            std::string name = value();
            o.format = format_from_name(name);
            if (!o.format) throw UsageError("--format expects obj, glb or ply, not '" + name + "'");
        } else if (arg == "--shading") {
            std::string name = value();
            if (name != "flat" && name != "smooth")
                throw UsageError("--shading expects flat or smooth, not '" + name + "'");
            o.export_options.shading = name == "flat" ? Shading::Flat : Shading::Smooth;
        } else if (arg == "--ply-ascii") {
            o.export_options.ply_binary = false;
        } else if (arg == "-o" || arg == "--output") {
            o.output = value();
        } else {
            throw UsageError("unknown option '" + arg + "'");
        }
    }
    return o;
}

TreeTemplate configured_template(const Options& o) {
    TreeTemplate tree = load_template(o.tree);
    for (const auto& [key, value] : o.sets) set_param(tree.params, key, value);
    if (o.seed) tree.params.seed = *o.seed;
    if (o.steps) tree.params.generations = *o.steps;
    return tree;
}

void print_help(std::FILE* to) {
    std::fputs(kHelp, to);
    for (const ParamInfo& p : param_infos())
        std::fprintf(to, "  %-17s %s (%g to %g)\n", std::string(p.key).c_str(),
                     std::string(p.help).c_str(), p.min, p.max);
}

void print_parts(const std::vector<NamedMesh>& parts, const char* indent) {
    for (const NamedMesh& part : parts) {
        // Leaves are open quads by design; the solid parts must be closed.
        const char* state = !part.closed ? "open by design"
                            : check_topology(*part.mesh).is_closed_manifold() ? "closed"
                                                                              : "NOT closed";
        std::printf("%s%-7s %zu triangles, %zu vertices, %s\n", indent, part.name.c_str(),
                    part.mesh->triangles.size(), part.mesh->positions.size(), state);
    }
}

int run_export(const Options& o) {
    if (o.output.empty()) throw UsageError("export needs -o OUT.obj|OUT.glb|OUT.ply");
    std::optional<ExportFormat> format = o.format ? o.format : format_from_extension(o.output);
    if (!format)
        throw UsageError("cannot tell the format of '" + o.output +
                         "': use .obj, .glb or .ply, or --format");
    TreeTemplate tmpl = configured_template(o);
    Tree tree = generate_tree(tmpl, o.mesh);

    TreeBudget budget;
    budget.total = o.budget ? *o.budget : static_cast<std::size_t>(tmpl.params.triangle_budget);
    budget.trunk = o.budget_trunk;
    budget.crown = o.budget_crown;
    const bool reduce = budget.total > 0 || budget.trunk || budget.crown;
    auto start = std::chrono::steady_clock::now();
    std::vector<std::filesystem::path> files;
    std::vector<ReducedTree> levels;
    if (o.lod) {
        std::size_t finest = budget.total > 0 ? budget.total : 800;
        std::vector<std::size_t> budgets = lod_budgets(finest, 4);
        levels = make_lod_chain(tree, budgets);
        std::vector<std::vector<NamedMesh>> named;
        for (size_t i = 0; i < levels.size(); ++i) {
            named.push_back(tree_parts(levels[i].trunk, levels[i].crown, tree.leaves, tmpl.colors));
            for (NamedMesh& part : named.back()) part.name += "_LOD" + std::to_string(i);
        }
        files = write_lod_chain(o.output, named, o.export_options, format);
    } else if (reduce) {
        levels.push_back(reduce_tree(tree, budget));
        files = write_model(o.output, tree_parts(levels[0].trunk, levels[0].crown, tree.leaves, tmpl.colors),
                            o.export_options, format);
    } else {
        files = write_model(o.output, tree_parts(tree.trunk, tree.crown, tree.leaves, tmpl.colors),
                            o.export_options, format);
    }
    double reduce_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    for (const auto& file : files) std::printf("wrote %s\n", file.string().c_str());
    std::printf("  marching cubes:\n");
    print_parts(tree_parts(tree.trunk, tree.crown, tree.leaves, tmpl.colors), "    ");
    for (size_t i = 0; i < levels.size(); ++i) {
        if (o.lod) std::printf("  LOD%zu (budget %zu):\n", i, lod_budgets(budget.total > 0 ? budget.total : 800, 4)[i]);
        else std::printf("  reduced (budget %zu):\n", budget.total);
        print_parts(tree_parts(levels[i].trunk, levels[i].crown, {}, tmpl.colors), "    ");
        if (!levels[i].note.empty()) std::printf("    note: %s\n", levels[i].note.c_str());
    }
    std::printf("  skeleton: %zu segments, %zu tips\n"
                "  time: derive %.1f ms, turtle %.1f ms, trunk mesh %.1f ms, crown mesh %.1f ms, "
                "leaves %.1f ms, reduce + write %.1f ms\n",
                tree.skeleton.segments.size(), tips(tree.skeleton).size(), tree.times.derive_ms,
                tree.times.turtle_ms, tree.times.trunk_mesh_ms, tree.times.crown_mesh_ms,
                tree.times.leaves_ms, reduce_ms);
    if (o.fidelity) {
        Mesh reference = reference_surface(tmpl, 200, o.mesh);
        const Mesh& trunk = levels.empty() ? tree.trunk : levels[0].trunk;
        const Mesh& crown = levels.empty() ? tree.crown : levels[0].crown;
        Fidelity f = measure_tree_fidelity(trunk, crown, reference);
        std::printf("  fidelity to the resolution-200 surface: mean %.3f %% max %.3f %% of the "
                    "height %.2f m (%zu samples)\n",
                    f.mean_percent, f.max_percent, f.height, f.samples);
    }
    return kOk;
}

int run_derive(const Options& o) {
    std::string text = derive_word(configured_template(o)).to_string();
    text.push_back('\n');
    std::fwrite(text.data(), 1, text.size(), stdout);
    return kOk;
}

int run_skeleton(const Options& o) {
    if (o.output.empty()) throw UsageError("skeleton needs -o skeleton.json");
    TreeTemplate tree = configured_template(o);
    Skeleton skeleton = grow_skeleton(tree);
    write_skeleton_json(o.output, skeleton, tree.params);
    std::printf("wrote %s: %zu segments, %zu tips\n", o.output.c_str(), skeleton.segments.size(),
                tips(skeleton).size());
    return kOk;
}

int run(int argc, char** argv) {
    Options o = parse_options(argc, argv);
    if (o.command == "--help" || o.command == "-h" || o.command == "help") {
        print_help(stdout);
        return kOk;
    }
    if (o.command == "templates") {
        for (const TreeTemplate* t : builtin_templates())
            std::printf("%s\t%s\n", t->name.c_str(), t->description.c_str());
        return kOk;
    }
    if (o.command == "export") return run_export(o);
    if (o.command == "derive") return run_derive(o);
    if (o.command == "skeleton") return run_skeleton(o);
    throw UsageError("unknown command '" + o.command + "'");
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "sylva: %s\n(see sylva --help)\n", e.what());
        return kUsage;
    } catch (const GrammarError& e) {
        std::fprintf(stderr, "sylva: grammar error: %s\n", e.what());
        return kInvalidInput;
    } catch (const InputError& e) {
        std::fprintf(stderr, "sylva: %s\n", e.what());
        return kInvalidInput;
    } catch (const IoError& e) {
        std::fprintf(stderr, "sylva: %s\n", e.what());
        return kIoError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sylva: internal error: %s\n", e.what());
        return 1;
    }
}
