// sylva: the headless command-line interface (docs/cli.md).
// Exit codes: 0 ok, 2 usage, 3 invalid input, 4 I/O error.
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_invoke.h>

#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "app/forest_cli.h"
#include "app/impostor_cli.h"
#include "app/infer_cli.h"
#include "app/lint_cli.h"
#include "core/atomic_file.h"
#include "core/color_variation.h"
#include "core/errors.h"
#include "core/file_set.h"
#include "core/name_list.h"
#include "core/output_folder.h"
#include "core/seed.h"
#include "core/stopwatch.h"
#include "export/export_tree.h"
#include "export/skeleton_json.h"
#include "platform/large_pages.h"
#include "platform/signal_cleanup.h"
#ifdef SYLVA_HAS_LAYOUT
#include "app/layout_cli.h"
#endif
#include "core/mesh_checks.h"
#include "marching/mesher.h"
#include "tree/cost.h"
#include "tree/growth.h"
#include "tree/leaf_thinning.h"
#include "tree/parameter_help.h"
#include "tree/parameters.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"
#include "tree/template_setting.h"
#include "turtle/lsystem_growth.h"
#include "turtle/lsystem_params.h"

namespace {

using namespace sylva;

constexpr int kOk = 0, kUsage = 2, kInvalidInput = 3, kIoError = 4;
// Beyond the 15 generations of a tree, grammar experiments (ABOP Fig. 1.31a takes 30 steps)
// may ask for more; growing words stop at the module cap long before this.
constexpr int kMaxSteps = 1000;

constexpr const char* kHelp = R"(sylva: low-poly trees from L-systems

Usage:
  sylva export   [-t NAME|FILE] [--set KEY=VALUE]... [--seed N] [--budget N]
                 [--budget-leaves N] [--crown-shape S] [--lod] [--mesher KIND]
                 -o OUT.{obj,glb,ply,fbx}
  sylva derive   [-t NAME|FILE] [--steps N] [--seed N] [--lint] [-o WORD.txt]
  sylva lint     [-t NAME|FILE] [--set KEY=VALUE]...
                 (grammar warnings as FILE:LINE:COLUMN; docs/grammar.md "Warnings")
  sylva skeleton [-t NAME|FILE] [--set KEY=VALUE]... [--seed N] -o skeleton.json
  sylva batch    -t NAME|FILE --count N [--seed S] [--jitter J|NAME=J]... [--shard I/N] -o DIR/
  sylva forest   [--area WxD | --ground FILE | --layout PLAN] [--species A,B:2,...] -o FOREST.glb
  sylva templates
  sylva layout   examples | derive EXAMPLE -o grammar.json |
                 generate EXAMPLE|GRAMMAR [--count N] [--size N] [--seed S] -o DIR/
                 (2D plans grown from one example; see sylva layout --help, docs/layout.md)
  sylva --help, sylva COMMAND --help, sylva --version
)";

// The flags of export, derive and skeleton (and the tree flags batch and forest share).
constexpr const char* kOptions = R"(
  -t NAME|FILE     a built-in template (see `sylva templates`) or a grammar file;
                   default: the built-in default tree
  --set KEY=VALUE  override a parameter (keys below) or a #define constant of the
                   template's rules (`#define a 46 # [20, 75] ...`: held to the comment's
                   range, whole numbers when the range is); may be repeated
  --seed N         seed of stochastic rules and rand(): 0 to 2^53 - 1 (default 1)
  --steps N        derivation steps (default: the template's generations)
  --mesher KIND    @MESHERS@
  --adaptivity A   vdb mesher only: 0 (uniform, default) to 1 (merge flat regions)
  --budget N       trunk + crown reduced to N triangles (quadric decimation, stays closed);
                   0 keeps every triangle; default: the template's triangle_budget (800)
  --budget-trunk N, --budget-crown N
                   a budget per part instead
  --budget-leaves N
                   leaves are budgeted apart from trunk + crown: at most N leaf triangles
                   (0: no leaves); default: the same as --budget (an 800-triangle tree
                   carries at most 800 leaf triangles more), every leaf with --budget 0.
                   Leaves are thinned, not reduced: an even, seeded subset of whole leaves
                   is kept, each grown (up to 2x) so the crown looks as dense
  --crown-shape S  how a reduced crown is drawn; default: the template's crown_shape
@CROWN_SHAPES@  --lod            LOD0-LOD3 with budgets N, N/2, N/4, N/8 (leaves halve alike): one .glb
                   with a node per level, or OUT_LOD0.obj ... (names game engines pick up)
  --impostor       append far levels baked from LOD0 (docs/impostors.md): an octahedral
                   impostor (one quad, albedo + normal/depth atlas of 8 x 8 views, a
                   shader per engine in engine_kits/) as the last level of a --lod chain,
                   or after the tree as LOD1; .glb embeds the atlas, .obj writes
                   OUT_impostor_albedo.png ... beside it; OUT_impostor.json has the layout
  --impostor-kind K
                   octahedral (default), billboard (crossed quads any importer shows) or
                   both (billboard, then octahedral); implies --impostor
  --impostor-size PX, --impostor-views N, --impostor-quads Q
                   atlas side (default auto: per tree), N x N views (default 8, 2 to 32),
                   billboard quads (default 3, or 2)
  --format F       @FORMATS@ (default: from the extension of OUT)
  --shading S      flat (default, faceted) or smooth normals
  --profile P      collision names, the wind channel, OBJ/PLY units (docs/engines.md):
@PROFILES@  --engine-kit DIR also write the profile's engine import kit (Godot, Unity, Unreal
                   scripts and shaders; all of them for generic) into DIR (docs/engines.md)
  --collision on|off
                   convex collision hulls (trunk, crown pieces); default: on for unity,
                   unreal and godot, off for generic
  --palette        UVs into a small palette texture of colour swatches (a row per part,
                   four shades), embedded in a .glb or written as OUT_palette.png beside
                   an .obj (its map_Kd)
  --no-uvs, --no-wind
                   leave out the UVs (bark, leaf cards, crown projection) or the wind data
  --tint-variation V, --crown-occlusion V
                   0 to 1 (default 0: flat colours): a seeded tint per branch, crown piece
                   and leaf (vertex colours; the parameter color_variation instead shifts
                   the whole tree's colours per seed); darkening toward the crown's middle
  --ply-ascii      write PLY as text instead of binary
  --fidelity       also report the distance of the reduced trunk + crown to the
                   resolution-200 surface and back (what the game mesh lost), in
                   percent of the tree's height
  -o PATH          output file. All files of an export (an .obj and its .mtl, every LOD)
                   are written to a temporary folder beside it and moved into place only
                   when all succeeded: on an error or SIGINT/SIGTERM nothing new is left
                   and existing files are untouched. A symlink is written through (the
                   file it points to is replaced); a directory, device or FIFO is refused
                   (exit 4)
  --max-memory MB, --max-seconds S
                   the cost is estimated before any work starts (word, segments, grid
                   cells, memory, time on two cores); export, skeleton and derive refuse
                   (exit 3, naming the estimate) a tree estimated above 2000 MB or 10 s
                   unless these limits are raised; batch and forest also refuse a whole
                   job (every tree together) above 2000 MB or 600 s

Exit codes: 0 ok, 2 usage, 3 invalid input, 4 I/O error.

)";

// kOptions with the names of the registries' entries (meshers, crown shapes, formats) put in.
std::string options_help() {
    std::string text = kOptions;
    auto put = [&](std::string_view mark, const std::string& with) {
        text.replace(text.find(mark), mark.size(), with);
    };
    std::string meshers;
    for (const MesherInfo& m : sylva::meshers())
        meshers += (meshers.empty() ? "" : "\n                   ") + std::string(m.name) + ": " +
                   std::string(m.help);
    put("@MESHERS@", meshers);
    std::string shapes;
    for (const CrownShapeInfo& c : crown_shapes())
        shapes += "                   " + std::string(c.name) + ": " + std::string(c.help) + "\n";
    put("@CROWN_SHAPES@", shapes);
    put("@FORMATS@", format_names());
    std::string profiles;
    for (const ProfileInfo& p : engine_profiles())
        profiles +=
            "                   " + std::string(p.name) + ": " + std::string(p.summary) + "\n";
    put("@PROFILES@", profiles);
    return text;
}

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
    std::optional<std::size_t> budget, budget_trunk, budget_crown, budget_leaves;
    std::optional<CrownShape> crown_shape;  // unset: the template's
    bool lod = false;
    bool fidelity = false;
    bool lint = false;  // derive: the grammar's warnings on stderr first
    const ExportFormat* format = nullptr;
    ExportOptions export_options;
    CostLimits limits;
};

template <class T>
T parse_integer(const std::string& flag, const std::string& text) {
    T value{};
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
        throw UsageError(flag + " expects a whole number, not '" + text + "'");
    return value;
}

// A triangle budget flag, held to the triangle_budget parameter's range (core/tree_params):
// a budget past it (1e19) overflowed later arithmetic and acted like 1.
std::size_t parse_budget(const std::string& flag, const std::string& text) {
    const std::size_t budget = parse_integer<std::size_t>(flag, text);
    const double max = find_param("triangle_budget")->max;
    if (static_cast<double>(budget) > max)
        throw UsageError(flag + " must be 0 to " + std::to_string(static_cast<std::size_t>(max)) +
                         ", not " + text);
    return budget;
}

// A seed flag: a whole number of core/seed.h's range, as every file Sylva writes holds it.
std::uint64_t parse_seed_flag(const std::string& flag, const std::string& text) {
    const std::optional<std::uint64_t> seed = parse_seed(text);
    if (!seed)
        throw UsageError(flag + " expects a seed from " + seed_range_text() + ", not '" + text +
                         "'");
    return *seed;
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
            if (eq == std::string::npos)
                throw UsageError("--set expects KEY=VALUE, not '" + kv + "'");
            o.sets.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
        } else if (arg == "--seed") {
            o.seed = parse_seed_flag(arg, value());
        } else if (arg == "--steps") {
            o.steps = parse_integer<int>(arg, value());
            if (*o.steps < 0 || *o.steps > kMaxSteps)
                throw UsageError("--steps must be 0 to " + std::to_string(kMaxSteps));
        } else if (arg == "--mesher") {
            std::string name = value();
            std::optional<Mesher> mesher = mesher_from_name(name);
            if (!mesher)
                throw UsageError("--mesher expects " + name_list(mesher_names()) + ", not '" +
                                 name + "'");
            o.mesh.mesher = *mesher;
        } else if (arg == "--adaptivity") {
            std::string text = value();
            double a = -1.0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), a);
            if (error != std::errc() || end != text.data() + text.size() || !(a >= 0.0 && a <= 1.0))
                throw UsageError("--adaptivity expects a number from 0 to 1, not '" + text + "'");
            o.mesh.vdb_adaptivity = a;
        } else if (arg == "--budget") {
            o.budget = parse_budget(arg, value());
        } else if (arg == "--budget-trunk") {
            o.budget_trunk = parse_budget(arg, value());
        } else if (arg == "--budget-crown") {
            o.budget_crown = parse_budget(arg, value());
        } else if (arg == "--budget-leaves") {
            o.budget_leaves = parse_budget(arg, value());
        } else if (arg == "--crown-shape") {
            const std::string name = value();
            const CrownShapeInfo* shape = find_crown_shape(name);
            if (!shape)
                throw UsageError("--crown-shape expects " + name_list(crown_shape_names()) +
                                 ", not '" + name + "'");
            o.crown_shape = shape->shape;
        } else if (arg == "--lod") {
            o.lod = true;
        } else if (arg.rfind("--impostor", 0) == 0) {
            try {  // app/impostor_cli.h
                if (!parse_impostor_flag(arg, value, o.export_options.impostor))
                    throw UsageError("unknown option '" + arg + "'");
            } catch (const std::invalid_argument& e) {
                throw UsageError(e.what());
            }
        } else if (arg == "--fidelity") {
            o.fidelity = true;
        } else if (arg == "--lint") {
            o.lint = true;
        } else if (arg == "--format") {
            std::string name = value();
            o.format = format_from_name(name);
            if (!o.format)
                throw UsageError("--format expects " + format_names() + ", not '" + name + "'");
        } else if (arg == "--shading") {
            std::string name = value();
            if (name != "flat" && name != "smooth")
                throw UsageError("--shading expects flat or smooth, not '" + name + "'");
            o.export_options.shading = name == "flat" ? Shading::Flat : Shading::Smooth;
        } else if (arg == "--profile") {
            std::string name = value();
            const std::optional<EngineProfile> profile = profile_from_name(name);
            if (!profile)
                throw UsageError("--profile expects " + profile_names() + ", not '" + name + "'");
            o.export_options.profile = *profile;
        } else if (arg == "--collision") {
            std::string state = value();
            if (state != "on" && state != "off")
                throw UsageError("--collision expects on or off, not '" + state + "'");
            o.export_options.engine.collision = state == "on";
        } else if (arg == "--engine-kit") {
            o.export_options.engine_kit = value();
        } else if (arg == "--palette") {
            o.export_options.engine.palette = true;
        } else if (arg == "--no-uvs") {
            o.export_options.engine.uvs = false;
        } else if (arg == "--no-wind") {
            o.export_options.engine.wind = false;
        } else if (arg == "--tint-variation" || arg == "--crown-occlusion") {
            const std::string text = value();
            double v = -1.0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
            if (error != std::errc() || end != text.data() + text.size() || !(v >= 0.0 && v <= 1.0))
                throw UsageError(arg + " expects a number from 0 to 1, not '" + text + "'");
            (arg == "--tint-variation" ? o.export_options.engine.color_variation
                                       : o.export_options.engine.crown_occlusion) =
                static_cast<float>(v);
        } else if (arg == "--ply-ascii") {
            o.export_options.ply_binary = false;
        } else if (arg == "--max-memory") {
            o.limits.max_bytes =
                1e6 * static_cast<double>(parse_integer<std::uint64_t>(arg, value()));
        } else if (arg == "--max-seconds") {
            o.limits.max_seconds = static_cast<double>(parse_integer<std::uint64_t>(arg, value()));
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
    for (const auto& [key, value] : o.sets) set_template_value(tree, key, value);
    if (o.seed) tree.params.seed = *o.seed;
    if (o.steps) tree.params.blocks.edit<LSystemParams>().generations = *o.steps;
    tree.colors = tree_colors(tree);  // colour variation: per seed
    return tree;
}

constexpr const char* kRaiseLimits = "raise the limits with --max-memory MB / --max-seconds S";

// The flags, then the growth methods and parameters from the registry (tree/parameter_help.h).
void print_options(std::FILE* to) {
    std::fputs(options_help().c_str(), to);
    std::fputs(parameter_help().c_str(), to);
}

void print_help(std::FILE* to) {
    std::fputs(kHelp, to);
    print_options(to);
    print_forest_help(to);
    print_infer_help(to);
}

// `sylva COMMAND --help`: the command's usage lines from kHelp (a line "  sylva COMMAND"
// and the indented lines under it), then the flags it takes. False for no such command.
bool print_command_help(const std::string& command, std::FILE* to) {
    if (command == "batch" || command == "forest") {
        print_forest_command_help(command, to);
        std::fputs("\nTree flags, as export takes them:", to);
        print_options(to);
        return true;
    }
    const std::string text = kHelp, head = "  sylva " + command;
    std::size_t at = text.find(head + " ");
    if (at == std::string::npos) at = text.find(head + "\n");
    if (at == std::string::npos) return false;
    std::string usage = "Usage:\n";
    for (std::size_t line = at; line < text.size();) {
        const std::size_t end = std::min(text.find('\n', line), text.size());
        const std::string row = text.substr(line, end - line);
        if (line != at && (row.rfind("  sylva ", 0) == 0 || row.rfind("    ", 0) != 0)) break;
        usage += row + "\n";
        line = end + 1;
    }
    std::fputs(usage.c_str(), to);
    if (command == "templates") return true;
    print_options(to);
    return true;
}

// `--help` or `-h` anywhere after the command.
bool asks_for_help(int argc, char** argv) {
    for (int i = 2; i < argc; ++i)
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") return true;
    return false;
}

// What each part is: "closed", "NOT closed" or its leaf count; the solid parts are checked
// on every core (the raw marching-cubes meshes are big).
std::vector<std::string> part_states(const std::vector<NamedMesh>& parts) {
    std::vector<std::string> states(parts.size());
    tbb::parallel_for(std::size_t{0}, parts.size(), [&](std::size_t k) {
        const Mesh& mesh = *parts[k].mesh;
        // Leaves are open by design (and counted); the solid parts must be closed.
        states[k] = !parts[k].closed ? std::to_string(count_leaves(mesh)) +
                                           (parts[k].name == "organs" ? " pieces" : " leaves") +
                                           ", open by design"
                    : check_topology(mesh).is_closed_manifold() ? "closed"
                                                                : "NOT closed";
    });
    return states;
}

void print_parts(const std::vector<NamedMesh>& parts, const std::vector<std::string>& states,
                 const char* indent) {
    for (std::size_t k = 0; k < parts.size(); ++k)
        std::printf("%s%-7s %zu triangles, %zu vertices, %s\n", indent, parts[k].name.c_str(),
                    parts[k].mesh->triangles.size(), parts[k].mesh->positions.size(),
                    states[k].c_str());
}

int run_export(const Options& o) {
    if (o.output.empty()) {
        std::string outs;
        for (std::string_view extension : format_extensions())
            outs += (outs.empty() ? "OUT" : "|OUT") + std::string(extension);
        throw UsageError("export needs -o " + outs);
    }
    const ExportFormat* by_extension = format_from_extension(o.output);
    const ExportFormat* format = o.format ? o.format : by_extension;
    if (!format)
        throw UsageError("cannot tell the format of '" + o.output + "': use " +
                         name_list(format_extensions()) + ", or --format");
    // PLY bytes in a .glb open in no engine: an extension of another format is a mistake.
    if (by_extension && by_extension != format)
        throw UsageError("--format " + std::string(format->name) + " does not match '" + o.output +
                         "' (a " + std::string(by_extension->name) +
                         " file name): use the extension " + std::string(format->extension));
    if (o.export_options.impostor.kind != ImpostorKind::None && format->name == "ply")
        throw UsageError("--impostor needs textures, which PLY does not carry: use .glb or .obj");
    output_target(o.output);  // a directory or device at -o is refused before the work
    OutputFolder folder(std::filesystem::path(o.output).parent_path());  // made, or exit 4
    TreeTemplate tmpl = configured_template(o);
    FinishSettings finish;
    finish.budget.total =
        o.budget ? *o.budget : static_cast<std::size_t>(tmpl.params.triangle_budget);
    finish.budget.trunk = o.budget_trunk;
    finish.budget.crown = o.budget_crown;
    finish.budget.leaves = o.budget_leaves;
    finish.budget.crown_shape = o.crown_shape;
    finish.lod = o.lod;
    MeshOptions mesh = o.mesh;
    mesh.budget = game_budget(finish);
    mesh.growth_limits = growth_limits(o.limits, kRaiseLimits);
    check_cost(estimate_cost(tmpl, mesh.budget), o.limits, kRaiseLimits);
    Tree tree = generate_tree(tmpl, mesh);
    // The reduction's cost depends on the meshes (their handles): known only now.
    check_cost(estimate_reduction_cost(tree, mesh.budget), o.limits, kRaiseLimits);

    // The raw meshes' summary is checked while the reduction runs: it needs nothing of it,
    // and a core is often free (the reduction of a big trunk waits for nothing either).
    std::vector<NamedMesh> raw = tree_parts(tree.trunk, tree.crown, tree.leaves, tmpl.colors);
    if (!tree.organs.empty())
        raw.push_back({"organs", &tree.organs.mesh, tmpl.colors.leaves, false});
    std::vector<std::string> raw_states;
    Stopwatch clock;
    FinishedTree finished;
    std::vector<std::filesystem::path> files;
    std::string impostor_layout;
    tbb::parallel_invoke(
        [&] {
            finished = finish_tree(tree, finish);
            ExportOptions export_options = o.export_options;
            export_options.engine.seed = tmpl.params.seed;  // colour variation and wind phases
            export_options.material_prefix = material_prefix(tmpl.name, tmpl.params.seed);
            export_options.engine.wind_motion = wind_motion(tmpl.params);  // for the kits
            files = write_tree(o.output, tree, finished, tmpl.colors, export_options, format,
                               &impostor_layout);
        },
        [&] { raw_states = part_states(raw); });
    folder.keep();
    tree.times.push_back({"reduce + write", clock.lap_ms()});

    for (const auto& file : files) std::printf("wrote %s\n", file.string().c_str());
    std::printf("  marching cubes:\n");
    print_parts(raw, raw_states, "    ");
    for (const std::string& note : tree.notes) std::printf("    note: %s\n", note.c_str());
    for (size_t i = 0; i < finished.levels.size(); ++i) {
        const ReducedTree& level = finished.levels[i];
        const std::size_t leaves = finished.leaf_budgets[i];
        const std::string leaf_budget =
            leaves == SIZE_MAX ? "every leaf" : std::to_string(leaves) + " leaf triangles";
        if (finished.lod)
            std::printf("  LOD%zu (budget %zu + %s):\n", i, finished.budgets[i],
                        leaf_budget.c_str());
        else
            std::printf("  reduced (budget %zu + %s):\n", finished.budgets[i], leaf_budget.c_str());
        std::vector<NamedMesh> parts =
            tree_parts(level.trunk, level.crown, level.leaves, tmpl.colors);
        if (i < finished.organs.size() && !finished.organs[i].empty())
            parts.push_back({"organs", &finished.organs[i].mesh, tmpl.colors.leaves, false});
        print_parts(parts, part_states(parts), "    ");
        if (!level.note.empty()) std::printf("    note: %s\n", level.note.c_str());
    }
    print_far_levels(o.export_options.impostor,
                     finished.levels.empty() ? 1 : finished.levels.size(), impostor_layout);
    std::printf("  skeleton: %zu segments, %zu tips\n  time:", tree.skeleton.segments.size(),
                tips(tree.skeleton).size());
    for (size_t i = 0; i < tree.times.size(); ++i)
        std::printf("%s %s %.1f ms", i ? "," : "", tree.times[i].name.c_str(), tree.times[i].ms);
    std::printf("\n");
    if (o.fidelity) {
        Mesh reference = reference_surface(tmpl, 200, o.mesh);
        const SolidParts solids = finest_solids(tree, finished);
        Fidelity f = measure_tree_fidelity(solids.trunk, solids.crown, reference);
        std::printf(
            "  fidelity to the resolution-200 surface: mean %.3f %% max %.3f %% of the "
            "height %.2f m (%zu samples)\n",
            f.mean_percent, f.max_percent, f.height, f.samples);
        const Fidelity b = measure_tree_loss(solids.trunk, solids.crown, reference, f.height);
        std::printf("  and back, from that surface: mean %.3f %% max %.3f %%\n", b.mean_percent,
                    b.max_percent);
    }
    return kOk;
}

int run_derive(const Options& o) {
    std::optional<OutputFolder> folder;  // refused or made before the work, as export's
    if (!o.output.empty()) {
        output_target(o.output);
        folder.emplace(std::filesystem::path(o.output).parent_path());
    }
    const TreeTemplate tree = configured_template(o);
    if (tree.growth != lsystem_growth.name)
        throw InputError("derive prints an L-system's word, but '" + tree.name + "' grows by " +
                         tree.growth);
    if (o.lint) print_lint(tree, stderr);
    check_cost(estimate_cost(tree, 0, false), o.limits, kRaiseLimits);
    std::string text = derive_word(tree).to_string();
    text.push_back('\n');
    if (o.output.empty()) {
        std::fwrite(text.data(), 1, text.size(), stdout);
    } else {
        write_file_atomically(o.output, [&](std::ostream& out) { out << text; });
        folder->keep();
        std::printf("wrote %s: %zu characters\n", o.output.c_str(), text.size() - 1);
    }
    return kOk;
}

int run_skeleton(const Options& o) {
    if (o.output.empty()) throw UsageError("skeleton needs -o skeleton.json");
    output_target(o.output);
    OutputFolder folder(std::filesystem::path(o.output).parent_path());
    TreeTemplate tree = configured_template(o);
    check_cost(estimate_cost(tree, 0, false), o.limits, kRaiseLimits);
    GrowthContext context;
    context.limits = growth_limits(o.limits, kRaiseLimits);
    Skeleton skeleton = grow(tree, context);
    write_skeleton_json(o.output, skeleton, tree.params);
    folder.keep();
    std::printf("wrote %s: %zu segments, %zu tips\n", o.output.c_str(), skeleton.segments.size(),
                tips(skeleton).size());
    return kOk;
}

int run(int argc, char** argv) {
    if (argc == 2 && (std::string(argv[1]) == "--version" || std::string(argv[1]) == "-V")) {
        std::printf("sylva %s\n", SYLVA_VERSION);
        return kOk;
    }
    // `sylva export --help`: that command's usage (layout prints its own).
    if (argc >= 3 && asks_for_help(argc, argv) && std::string(argv[1]) != "layout" &&
        std::string(argv[1]) != "infer") {
        if (!print_command_help(argv[1], stdout))
            throw UsageError("unknown command '" + std::string(argv[1]) + "'");
        return kOk;
    }
    // The many-tree commands parse their own flags (app/forest_cli.h).
    if (argc >= 2 && std::string(argv[1]) == "batch") return run_batch_command(argc, argv);
    if (argc >= 2 && std::string(argv[1]) == "forest") return run_forest_command(argc, argv);
    if (argc >= 2 && std::string(argv[1]) == "infer") return run_infer_command(argc, argv);
#ifdef SYLVA_HAS_LAYOUT
    // `sylva layout ...` (app/layout_cli.h) parses its own arguments.
    if (argc >= 2 && std::string(argv[1]) == "layout")
        return run_layout_cli(std::vector<std::string>(argv + 1, argv + argc), stdout, stderr);
#endif
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
    if (o.command == "lint") return run_lint(configured_template(o));
    if (o.command == "skeleton") return run_skeleton(o);
    throw UsageError("unknown command '" + o.command + "'");
}

}  // namespace

int main(int argc, char** argv) {
    if (!std::getenv("SYLVA_NO_LARGE_PAGES")) use_large_pages();  // platform/large_pages.h
    // SIGINT/SIGTERM during a write remove the export's temporaries before the process ends.
    install_signal_cleanup();
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
