#include "app/forest_cli.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/impostor_cli.h"
#include "core/errors.h"
#include "core/seed.h"
#include "export/export.h"
#include "forest/batch.h"
#include "forest/forest.h"
#include "forest/species_file.h"
#include "forest/variation.h"
#include "tree/cost.h"
#include "tree/parameters.h"
#include "tree/template_library.h"
#include "tree/template_setting.h"

namespace sylva {
namespace {

constexpr int kOk = 0, kUsage = 2;

constexpr const char* kForestHelp = R"(
Many trees:
  sylva batch  -t NAME|FILE --count N [--seed S] [--jitter J] [--jitter NAME=J]...
               [--shard I/N]
               [--set KEY=VALUE]... [--budget N] [--lod] [--format F] -o DIR/
      N variants of one template: variant i is seeded with the top 53 bits of the i-th
      splitmix64 number of S (default 1) and, with --jitter J (0 to 1, default 0.1), has
      branch_length, branch_width, angles, tapers, crown, leaf and envelope sizes scaled
      by up to +-J (within their ranges). --jitter NAME=J (repeatable) also scales a
      #define of the template's rules (held to its `# [lo, hi]` comment's range, whole
      numbers when the range is) or another parameter by up to +-J. Writes DIR/<template>_<i>.<ext> and DIR/manifest.json
      (file, seed, jittered parameters, triangles per item). --shard I/N writes only the
      items whose index modulo N is I-1, and manifest_<I>of<N>.json: run 1/N..N/N on any
      machines (GNU parallel, a Slurm array) and their files together are the whole batch.
      A shard is written all or nothing.
  sylva forest [--area WxD | --ground FILE.json | --layout FILE.json]
               [--species NAME[:WEIGHT],... | --species-file FILE.json]
               [--variants K] [--spacing M] [--density D | --trees N] [--seed S]
               [--stand-size M] [--jitter J (default 0.2)] [--min-age A] [--scale-jitter S]
               [--instancing nodes|gpu] [--budget N] [--lod] [--impostor...] -o FOREST.glb
      Plants a ground: a W x D meter rectangle (default 100x100) or the "forest" polygons
      of a JSON file {"polygons": [{"points": [[x, y], ...], "class": "forest"}]} (other
      classes are holes). Trees stand at least --spacing apart (default 4 m, Poisson disk),
      thinned to --density trees per hectare or --trees N; species (default oak; a file:
      {"species": [{"template": "oak", "weight": 2, "set": {"age": 0.8}}]}) grow in
      stands about --stand-size meters across (default 40) by 2D noise, in proportion to
      their weights. Each species has K (default 8) unique variants, reused turned, scaled
      by 1 +- S (default 0.15) and aged from A (default 0.6) to 1 times the template's
      age. Writes FOREST.glb (meshes stored once: nodes sharing meshes, or with
      --instancing gpu EXT_mesh_gpu_instancing), FOREST.placements.csv and .json.
      --impostor and --impostor-kind/-size/-views/-quads (as `sylva export`) add each
      variant's far levels: one bake and one set of images per variant, shared by its trees.
      --layout FILE.json plants a plan from `sylva layout generate` (same form, each
      polygon's "class"): forest as above; orchard: rows along each polygon's longest
      edge, --row-spacing M (default 6) apart, --tree-spacing M (default 4) in a row, at
      least --orchard-margin M (default 2) inside, of --orchard-species NAME[:WEIGHT],...
      (default oak; one species per polygon); meadow: --meadow-density D solitary
      trees per hectare (default 0) of the forest species; path: nothing. A layout's
      coordinates are its example's drawing units, taken as meters times --layout-scale
      (default 1; the shipped examples are drawn on a 10-unit plot grid, so 4 gives 40 m
      plots). The placement lists give each tree's class.
)";

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

constexpr const char* kRaiseLimits = "raise the limits with --max-memory MB / --max-seconds S";

std::string figure(double n) {
    char text[32];
    std::snprintf(text, sizeof text, n < 1e7 ? "%.0f" : "%.3g", n);
    return text;
}

template <class T>
T parse_number(const std::string& flag, const std::string& text) {
    T value{};
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
        throw UsageError(flag + " expects a number, not '" + text + "'");
    if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(value)) throw UsageError(flag + " expects a finite number");
    return value;
}

// The flags every many-tree command shares with `export`.
struct TreeFlags {
    std::vector<std::pair<std::string, std::string>> sets;
    std::optional<std::size_t> budget, budget_leaves;
    bool lod = false;
    const ExportFormat* format = nullptr;
    ExportOptions export_options;
    std::optional<double> max_bytes, max_seconds;  // --max-memory, --max-seconds
    std::string output;
    std::uint64_t seed = 1;
    double jitter = 0.1;
    std::vector<KeyJitter> key_jitter;  // --jitter NAME=J

    // True when `arg` was one of them.
    bool parse(const std::string& arg, const std::function<std::string()>& value) {
        if (arg == "--set") {
            const std::string kv = value();
            const std::size_t eq = kv.find('=');
            if (eq == std::string::npos)
                throw UsageError("--set expects KEY=VALUE, not '" + kv + "'");
            sets.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
        } else if (arg == "--seed") {
            const std::string text = value();
            const std::optional<std::uint64_t> parsed = parse_seed(text);
            if (!parsed)
                throw UsageError(arg + " expects a seed from " + seed_range_text() + ", not '" +
                                 text + "'");
            seed = *parsed;
        } else if (arg == "--jitter") {
            // J, or NAME=J: a #define or parameter varied by up to +-J besides the usual set.
            const std::string text = value();
            const std::size_t eq = text.find('=');
            const double amount =
                parse_number<double>(arg, eq == std::string::npos ? text : text.substr(eq + 1));
            if (!(amount >= 0.0 && amount <= 1.0))
                throw UsageError("--jitter must be 0 to 1, not " + text);
            if (eq == std::string::npos)
                jitter = amount;
            else if (eq == 0)
                throw UsageError("--jitter expects J or NAME=J, not '" + text + "'");
            else
                key_jitter.push_back({text.substr(0, eq), amount});
        } else if (arg == "--budget") {
            budget = parse_number<std::size_t>(arg, value());
        } else if (arg == "--budget-leaves") {
            budget_leaves = parse_number<std::size_t>(arg, value());
        } else if (arg == "--lod") {
            lod = true;
        } else if (arg == "--format") {
            const std::string name = value();
            format = format_from_name(name);
            if (!format)
                throw UsageError("--format expects " + format_names() + ", not '" + name + "'");
        } else if (arg == "--shading") {
            const std::string name = value();
            if (name != "flat" && name != "smooth")
                throw UsageError("--shading expects flat or smooth, not '" + name + "'");
            export_options.shading = name == "flat" ? Shading::Flat : Shading::Smooth;
        } else if (arg == "--max-memory") {
            max_bytes = 1e6 * static_cast<double>(parse_number<std::uint64_t>(arg, value()));
        } else if (arg == "--max-seconds") {
            max_seconds = static_cast<double>(parse_number<std::uint64_t>(arg, value()));
        } else if (arg == "-o" || arg == "--output") {
            output = value();
        } else if (arg.starts_with("--impostor")) {
            try {
                return parse_impostor_flag(arg, value, export_options.impostor);
            } catch (const std::invalid_argument& e) {
                throw UsageError(e.what());
            }
        } else {
            return false;
        }
        return true;
    }

    TreeTemplate configured(const std::string& name) const {
        TreeTemplate tree = load_template(name);
        for (const auto& [key, text] : sets) set_template_value(tree, key, text);
        return tree;
    }

    FinishSettings finish(const TreeTemplate& tree) const {
        FinishSettings f;
        f.budget.total = budget ? *budget : static_cast<std::size_t>(tree.params.triangle_budget);
        f.budget.leaves = budget_leaves;
        f.lod = lod;
        return f;
    }

    // The flags over `defaults`: a tree's limits, or a whole job's (kManyTreeLimits).
    CostLimits limits(CostLimits defaults) const {
        if (max_bytes) defaults.max_bytes = *max_bytes;
        if (max_seconds) defaults.max_seconds = *max_seconds;
        return defaults;
    }

    // Each tree within a tree's limits, and the whole job within a job's, before any work.
    void check(const TreeTemplate& tree, const FinishSettings& f) const {
        check_cost(estimate_cost(tree, game_budget(f)), limits(CostLimits{}), kRaiseLimits);
    }
    // A tree's limits again, held while each grows (GrowthLimits).
    GrowthLimits growth_limits() const {
        return sylva::growth_limits(limits(CostLimits{}), kRaiseLimits);
    }
    void check_job(const Cost& job, const std::string& what) const {
        check_cost(job, limits(kManyTreeLimits), kRaiseLimits, what);
    }
};

// Runs `parse` over argv[2..], turning usage errors into exit code 2.
int with_flags(
    int argc, char** argv,
    const std::function<bool(const std::string&, const std::function<std::string()>&)>& parse,
    const std::function<int()>& run) {
    try {
        for (int i = 2; i < argc; ++i) {
            const std::string arg = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw UsageError(arg + " needs a value");
                return argv[++i];
            };
            if (!parse(arg, value)) throw UsageError("unknown option '" + arg + "'");
        }
        return run();
    } catch (const UsageError& e) {
        std::fprintf(stderr, "sylva: %s\n(see sylva --help)\n", e.what());
        return kUsage;
    }
}

}  // namespace

void print_forest_help(std::FILE* to) {
    std::fputs(kForestHelp, to);
}

void print_forest_command_help(const std::string& command, std::FILE* to) {
    const std::string text = kForestHelp;
    const std::size_t at = text.find("  sylva " + command + " ");
    const std::size_t next = text.find("\n  sylva ", at + 1);
    std::fputs("Usage:\n", to);
    std::fputs(
        text.substr(at, next == std::string::npos ? std::string::npos : next + 1 - at).c_str(), to);
}

int run_batch_command(int argc, char** argv) {
    TreeFlags flags;
    std::string tree_name = "default";
    std::optional<std::size_t> count;
    Shard shard;
    auto parse = [&](const std::string& arg, const std::function<std::string()>& value) {
        if (flags.parse(arg, value)) return true;
        if (arg == "-t" || arg == "--template") {
            tree_name = value();
        } else if (arg == "--count") {
            count = parse_number<std::size_t>(arg, value());
            if (*count == 0) throw UsageError("--count must be at least 1");
        } else if (arg == "--shard") {
            const std::string text = value();
            try {
                shard = parse_shard(text);
            } catch (const InputError& e) {
                throw UsageError(e.what());
            }
        } else {
            return false;
        }
        return true;
    };
    return with_flags(argc, argv, parse, [&] {
        if (!count) throw UsageError("batch needs --count N");
        if (flags.export_options.impostor.kind != ImpostorKind::None)
            throw UsageError("--impostor applies to sylva export and sylva forest, not batch");
        if (flags.output.empty()) throw UsageError("batch needs -o DIR/");
        BatchSettings settings;
        settings.tree = flags.configured(tree_name);
        settings.count = *count;
        settings.seed = flags.seed;
        settings.jitter = flags.jitter;
        settings.key_jitter = flags.key_jitter;
        check_key_jitter(settings.tree, settings.key_jitter);  // before any work, exit 3
        settings.finish = flags.finish(settings.tree);
        flags.check(settings.tree, settings.finish);
        settings.mesh.growth_limits = flags.growth_limits();
        // The whole shard, before a single item is planned (a count of 1e9 ended in bad_alloc).
        flags.check_job(
            estimate_batch_cost(settings),
            "this batch of " + figure(static_cast<double>(shard_size(settings))) + " trees");
        settings.format = flags.format;
        settings.export_options = flags.export_options;
        settings.shard = shard;
        settings.progress = [](std::size_t done, std::size_t total, const std::string& file) {
            std::fprintf(stderr, "batch: %zu/%zu %s\n", done, total, file.c_str());
        };
        const BatchResult result = run_batch(settings, flags.output);
        std::size_t triangles = 0;
        for (const BatchItem& item : result.items) triangles += item.triangles;
        std::printf("wrote %zu trees (%zu triangles) and %s to %s\n", result.items.size(),
                    triangles, manifest_file_name(shard).c_str(), flags.output.c_str());
        return kOk;
    });
}

int run_forest_command(int argc, char** argv) {
    TreeFlags flags;
    flags.jitter = 0.2;  // trees side by side: more variety than a batch's default
    forest::ForestSettings settings;
    std::vector<std::pair<std::string, double>> species{{"oak", 1.0}};
    // A fruit-tree stand-in: oak is about 5 m tall with a round crown 4-5 m across on a short
    // stout trunk, an apple tree's size and shape, and fits 6 m x 4 m rows; maple is 8 m
    // across and autumn-coloured, birch a slender 2 m column.
    std::vector<std::pair<std::string, double>> orchard_species{{"oak", 1.0}};
    std::optional<double> layout_scale;
    forest::LayoutPlanting layout;
    auto species_list = [](const std::string& flag, const std::string& list) {
        std::vector<std::pair<std::string, double>> out;
        std::size_t start = 0;
        while (start <= list.size()) {
            const std::size_t comma = std::min(list.find(',', start), list.size());
            std::string item = list.substr(start, comma - start);
            double weight = 1.0;
            const std::size_t colon = item.rfind(':');
            if (colon != std::string::npos) {
                weight = parse_number<double>(flag + " weight", item.substr(colon + 1));
                if (!(weight > 0.0))
                    throw UsageError(flag + ": the weight of '" + item.substr(0, colon) +
                                     "' must be positive, not " + item.substr(colon + 1));
                item.resize(colon);
            }
            if (item.empty()) throw UsageError(flag + " expects NAME[:WEIGHT],...");
            out.emplace_back(item, weight);
            start = comma + 1;
        }
        return out;
    };
    std::string species_file;
    std::string instancing = "nodes";
    // --area, --ground and --layout each say where to plant: one of them, once.
    std::string ground_flag;
    auto where = [&](const std::string& flag) {
        if (!ground_flag.empty() && ground_flag != flag)
            throw UsageError(ground_flag + " and " + flag +
                             " both say where to plant: give one of them");
        ground_flag = flag;
    };
    // A flag's bad value is a usage error (exit 2), whether it is no number or out of range;
    // the ranges are plan_forest()'s and orchard_rows()'s.
    auto positive = [](const std::string& flag, const std::string& text) {
        const double v = parse_number<double>(flag, text);
        if (!(v > 0.0)) throw UsageError(flag + " must be a positive number, not " + text);
        return v;
    };
    auto non_negative = [](const std::string& flag, const std::string& text) {
        const double v = parse_number<double>(flag, text);
        if (!(v >= 0.0)) throw UsageError(flag + " must be 0 or more, not " + text);
        return v;
    };
    auto fraction = [](const std::string& flag, const std::string& text, double hi) {
        const double v = parse_number<double>(flag, text);
        if (!(v >= 0.0 && v <= hi))
            throw UsageError(flag + " must be from 0 to " + figure(hi) + ", not " + text);
        return v;
    };
    auto parse = [&](const std::string& arg, const std::function<std::string()>& value) {
        if (flags.parse(arg, value)) return true;
        if (arg == "--area" || arg == "--ground" || arg == "--layout") where(arg);
        if (arg == "--area") {
            const std::string text = value();
            const std::size_t x = text.find('x');
            if (x == std::string::npos)
                throw UsageError("--area expects WxD in meters, not '" + text + "'");
            const double w = parse_number<double>(arg, text.substr(0, x));
            const double d = parse_number<double>(arg, text.substr(x + 1));
            if (!(w > 0 && d > 0)) throw UsageError("--area expects positive sizes");
            settings.ground = forest::rectangle_ground(w, d);
        } else if (arg == "--ground") {
            settings.ground = forest::load_ground(value());
        } else if (arg == "--layout") {
            settings.ground = forest::load_ground(value());
            settings.layout = layout;
        } else if (arg == "--layout-scale") {
            layout_scale = parse_number<double>(arg, value());
            if (!(*layout_scale > 0.0 && std::isfinite(*layout_scale)))
                throw UsageError("--layout-scale must be a positive number of meters per unit");
        } else if (arg == "--orchard-species") {
            orchard_species = species_list(arg, value());
        } else if (arg == "--row-spacing") {
            layout.orchard.row_spacing = positive(arg, value());
        } else if (arg == "--tree-spacing") {
            layout.orchard.tree_spacing = positive(arg, value());
        } else if (arg == "--orchard-margin") {
            layout.orchard.margin = non_negative(arg, value());
        } else if (arg == "--meadow-density") {
            layout.meadow_density = non_negative(arg, value());
        } else if (arg == "--species") {
            species = species_list(arg, value());
        } else if (arg == "--species-file") {
            species_file = value();
        } else if (arg == "--variants") {
            settings.variants = parse_number<std::size_t>(arg, value());
            if (settings.variants < 1 || settings.variants > 1000)
                throw UsageError("--variants must be 1 to 1000, not " +
                                 std::to_string(settings.variants));
        } else if (arg == "--spacing") {
            settings.spacing = positive(arg, value());
        } else if (arg == "--density") {
            settings.density = positive(arg, value());
        } else if (arg == "--trees") {
            settings.trees = parse_number<std::size_t>(arg, value());
        } else if (arg == "--stand-size") {
            settings.stand_size = positive(arg, value());
        } else if (arg == "--min-age") {
            settings.min_age = fraction(arg, value(), 1.0);
        } else if (arg == "--scale-jitter") {
            settings.scale_jitter = fraction(arg, value(), 0.9);
        } else if (arg == "--instancing") {
            instancing = value();
            if (instancing != "nodes" && instancing != "gpu")
                throw UsageError("--instancing expects nodes or gpu, not '" + instancing + "'");
        } else {
            return false;
        }
        return true;
    };
    return with_flags(argc, argv, parse, [&] {
        if (flags.output.empty()) throw UsageError("forest needs -o FOREST.glb");
        if (!flags.key_jitter.empty())
            throw UsageError("--jitter NAME=J varies a batch's trees; a forest takes --jitter J");
        if (settings.density && settings.trees)
            throw UsageError("--density and --trees both say how many trees: give one of them");
        if (flags.format && flags.format->name != "glb")
            throw UsageError("forest writes a .glb scene; --format must be glb");
        if (!species_file.empty()) {
            settings.species = forest::load_species(species_file);
            for (forest::Species& sp : settings.species)
                for (const auto& [key, text] : flags.sets) set_template_value(sp.tree, key, text);
        } else {
            for (const auto& [name, weight] : species)
                settings.species.push_back({flags.configured(name), weight});
        }
        if (settings.layout) {
            settings.layout = layout;  // the orchard and meadow flags, wherever they stood
            if (layout_scale) forest::scale_ground(settings.ground, *layout_scale);
            for (const auto& [name, weight] : orchard_species)
                settings.species.push_back(
                    {flags.configured(name), weight, std::string(forest::kOrchardClass)});
        } else if (layout_scale) {
            throw UsageError("--layout-scale only applies with --layout");
        }
        for (const forest::Species& sp : settings.species) {
            settings.finish = flags.finish(sp.tree);
            flags.check(sp.tree, settings.finish);
        }
        settings.mesh.growth_limits = flags.growth_limits();
        settings.seed = flags.seed;
        settings.jitter = flags.jitter;
        // Every variant and every tree together, before any is planted.
        flags.check_job(estimate_forest_cost(settings),
                        "this forest of up to " + figure(forest::estimated_trees(settings)) +
                            " trees and " +
                            figure(static_cast<double>(settings.variants) *
                                   static_cast<double>(settings.species.size())) +
                            " variants");
        settings.export_options = flags.export_options;
        settings.instancing =
            instancing == "gpu" ? forest::Instancing::Gpu : forest::Instancing::Nodes;
        settings.progress = [](std::size_t done, std::size_t total) {
            std::fprintf(stderr, "forest: variant %zu/%zu\n", done, total);
        };
        const forest::ForestResult result = forest::plant_forest(settings, flags.output);
        for (const auto& file : result.files) std::printf("wrote %s\n", file.string().c_str());
        std::vector<std::size_t> per_species(settings.species.size(), 0);
        for (const forest::Placement& p : result.plan.placements) ++per_species[p.species];
        std::printf("  %zu trees:", result.plan.placements.size());
        for (std::size_t s = 0; s < per_species.size(); ++s)
            std::printf("%s %s%s %zu", s ? "," : "", settings.species[s].tree.name.c_str(),
                        settings.species[s].cls == forest::kOrchardClass ? " (orchard)" : "",
                        per_species[s]);
        std::printf(
            "\n  %zu unique variants; time: plan %.0f ms, variants %.0f ms, write %.0f ms\n",
            result.plan.variants.size(), result.times.plan_ms, result.times.variants_ms,
            result.times.write_ms);
        if (settings.trees && result.plan.placements.size() < *settings.trees)
            std::printf("  note: a spacing of %g m fits only %zu of the %zu trees asked for\n",
                        settings.spacing, result.plan.placements.size(), *settings.trees);
        return kOk;
    });
}

}  // namespace sylva
