#include "forest/batch.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <charconv>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/color_variation.h"
#include "core/data_paths.h"
#include "core/errors.h"
#include "core/file_set.h"
#include "core/output_folder.h"
#include "export/export.h"
#include "export/glb_writer.h"
#include "forest/variation.h"
#include "platform/signal_cleanup.h"
#include "tree/parameters.h"
#include "tree/template_setting.h"

namespace sylva {
namespace {

// A generated tree kept until the shard is written: the finished levels, and the raw
// meshes only when they are what gets written (no budget).
struct Generated {
    Tree tree;
    FinishedTree finished;
};

std::size_t digits(std::size_t n) {
    std::size_t d = 1;
    while (n >= 10) {
        n /= 10;
        ++d;
    }
    return d;
}

std::size_t parse_count(const std::string& text, const std::string& part) {
    std::size_t value = 0;
    auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (part.empty() || error != std::errc() || end != part.data() + part.size())
        throw InputError("--shard expects I/N with whole numbers 1 <= I <= N, not '" + text + "'");
    return value;
}

std::size_t triangles_of(const std::vector<ModelParts>& levels) {
    std::size_t n = 0;
    if (!levels.empty())
        for (const NamedMesh& part : levels[0]) n += part.mesh->triangles.size();
    return n;
}

}  // namespace

Shard parse_shard(const std::string& text) {
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos)
        throw InputError("--shard expects I/N with whole numbers 1 <= I <= N, not '" + text + "'");
    const std::size_t i = parse_count(text, text.substr(0, slash));
    const std::size_t n = parse_count(text, text.substr(slash + 1));
    if (i < 1 || i > n)
        throw InputError("--shard expects I/N with whole numbers 1 <= I <= N, not '" + text + "'");
    return {i - 1, n};
}

std::string manifest_file_name(const Shard& shard) {
    if (shard.count <= 1) return "manifest.json";
    return "manifest_" + std::to_string(shard.index + 1) + "of" + std::to_string(shard.count) +
           ".json";
}

std::size_t shard_size(const BatchSettings& settings) {
    const Shard& shard = settings.shard;
    if (shard.count == 0 || shard.index >= settings.count) return 0;
    return (settings.count - shard.index - 1) / shard.count + 1;
}

Cost estimate_batch_cost(const BatchSettings& settings) {
    const std::size_t budget = game_budget(settings.finish);
    return many_trees_cost(estimate_cost(settings.tree, budget),
                           static_cast<double>(shard_size(settings)), budget);
}

std::vector<BatchItem> plan_batch(const BatchSettings& settings) {
    if (settings.count == 0) throw InputError("a batch needs a count of at least 1");
    if (settings.shard.count == 0 || settings.shard.index >= settings.shard.count)
        throw InputError("the shard index must be below the shard count");
    const ExportFormat* format = settings.format ? settings.format : &glb_format;
    const std::size_t width = std::max<std::size_t>(4, digits(settings.count - 1));
    std::vector<BatchItem> items;
    for (std::size_t i = settings.shard.index; i < settings.count; i += settings.shard.count) {
        BatchItem item;
        item.index = i;
        std::string number = std::to_string(i);
        number.insert(0, width - number.size(), '0');
        item.file =
            safe_file_name(settings.tree.name) + "_" + number + std::string(format->extension);
        item.seed = variant_seed(settings.seed, i);
        item.params = varied_params(settings.tree.params, item.seed, settings.jitter);
        item.keys = varied_keys(settings.tree, item.seed, settings.key_jitter);
        items.push_back(std::move(item));
    }
    return items;
}

TreeTemplate item_template(const BatchSettings& settings, const BatchItem& item) {
    TreeTemplate tree = settings.tree;
    tree.params = item.params;
    for (const auto& [key, value] : item.keys) set_template_value(tree, key, value);
    return tree;
}

BatchResult run_batch(const BatchSettings& settings, const std::filesystem::path& dir) {
    const ExportFormat* format = settings.format ? settings.format : &glb_format;
    BatchResult result;
    result.items = plan_batch(settings);
    const std::size_t n = result.items.size();
    OutputFolder folder(dir);  // made before the trees are, gone again if they fail

    MeshOptions mesh = settings.mesh;
    mesh.budget = game_budget(settings.finish);
    mesh.cancel = settings.cancel;
    mesh.progress = nullptr;
    FinishSettings finish = settings.finish;
    finish.decimate.cancel = settings.cancel;

    // Generate: items are independent; a chunk at a time in parallel, progress between.
    std::vector<std::unique_ptr<Generated>> generated(n);
    const std::size_t chunk = 8;
    for (std::size_t begin = 0; begin < n; begin += chunk) {
        const std::size_t end = std::min(n, begin + chunk);
        tbb::parallel_for(begin, end, [&](std::size_t k) {
            const TreeTemplate tree = item_template(settings, result.items[k]);
            auto g = std::make_unique<Generated>();
            g->tree = generate_tree(tree, mesh);
            g->finished = finish_tree(g->tree, finish);
            if (!g->finished.levels.empty()) {  // the raw meshes are not written: drop them
                g->tree.trunk = {};
                g->tree.crown = {};
                g->tree.leaves = {};
            }
            generated[k] = std::move(g);
        });
        throw_if_cancelled(settings.cancel);
        if (settings.progress)
            for (std::size_t k = begin; k < end; ++k)
                settings.progress(k + 1, n, result.items[k].file);
    }

    // Write: every file staged, then moved into place, with signals held back meanwhile so
    // an interrupt leaves all of the shard or none of it.
    SignalDeferral deferral;
    FileSet files;
    nlohmann::ordered_json items = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < n; ++k) {
        BatchItem& item = result.items[k];
        const TreeTemplate variant = item_template(settings, item);
        const std::vector<ModelParts> levels =
            finished_parts(generated[k]->tree, generated[k]->finished, tree_colors(variant),
                           material_prefix(settings.tree.name, item.seed));
        item.triangles = triangles_of(levels);
        format->write(files, dir / item.file, levels, settings.export_options);
        nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
        for (const JitterParam& p : jitter_params())
            if (auto value = get_param(item.params, p.key)) parameters[std::string(p.key)] = *value;
        for (const auto& [key, value] : item.keys) parameters[key] = value;
        items.push_back({{"index", item.index},
                         {"file", item.file},
                         {"seed", item.seed},
                         {"parameters", parameters},
                         {"triangles", item.triangles}});
        generated[k].reset();
    }
    nlohmann::ordered_json jittered = nlohmann::ordered_json::array();
    for (const JitterParam& p : jitter_params()) jittered.push_back(p.key);
    for (const KeyJitter& k : settings.key_jitter)
        if (std::find(jittered.begin(), jittered.end(), k.key) == jittered.end())
            jittered.push_back(k.key);
    const nlohmann::ordered_json manifest = {
        {"template", settings.tree.name},
        {"count", settings.count},
        {"seed", settings.seed},
        {"jitter", settings.jitter},
        {"shard", {settings.shard.index + 1, settings.shard.count}},
        {"format", format->name},
        {"jittered", jittered},
        {"items", items},
    };
    files.add(dir / manifest_file_name(settings.shard),
              [&](std::ostream& out) { out << manifest.dump(2) << '\n'; });
    result.files = files.commit();
    folder.keep();
    return result;
}

}  // namespace sylva
