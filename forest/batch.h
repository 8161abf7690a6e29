// `sylva batch`: N variants of one template (variation.h), written as N files plus a JSON
// manifest. A batch can be cut into shards (`--shard I/N`) that machines run apart: shard I
// writes the items whose index modulo N is I - 1, byte for byte as the whole batch writes
// them, and a manifest of its own items (manifest_file_name()).
//
// All or nothing per shard: the trees are generated first (in parallel, oneTBB) and kept in
// memory, then every file of the shard is staged and moved into place in one FileSet under
// a SignalDeferral, so SIGINT/SIGTERM (platform/signal_cleanup.h) leave either no new file or
// the whole shard.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/cancel.h"
#include "core/tree_template.h"
#include "export/export_tree.h"
#include "forest/variation.h"
#include "tree/cost.h"
#include "tree/pipeline.h"

namespace sylva {

// Shard `index` (0-based) of `count`.
struct Shard {
    std::size_t index = 0;
    std::size_t count = 1;
};

// "I/N" with 1 <= I <= N, as --shard takes it. Throws InputError naming the text.
Shard parse_shard(const std::string& text);

struct BatchSettings {
    TreeTemplate tree;  // parameters as configured (--set); its seed is ignored
    std::size_t count = 1;
    std::uint64_t seed = 1;                // the batch's base seed (variation.h)
    double jitter = 0.1;                   // varied_params(); 0: only the seed differs
    std::vector<KeyJitter> key_jitter;     // #defines and parameters varied besides (varied_keys)
    FinishSettings finish;                 // budget, LOD
    MeshOptions mesh;                      // its budget is set from `finish`
    const ExportFormat* format = nullptr;  // null: glb
    ExportOptions export_options;
    Shard shard;
    // Called after each tree is generated (from the calling thread): items done, items in
    // this shard, and the file name.
    std::function<void(std::size_t, std::size_t, const std::string&)> progress;
    CancelFlag cancel = nullptr;
};

// One variant: its index in the whole batch, file name (in the output folder), seed and
// parameters, and the triangles written (every part of the finest level).
struct BatchItem {
    std::size_t index = 0;
    std::string file;
    std::uint64_t seed = 0;
    TreeParams params;
    std::vector<std::pair<std::string, double>> keys;  // the key_jitter keys' values
    std::size_t triangles = 0;
};

// The template of one item: the settings' tree with the item's parameters and keys.
TreeTemplate item_template(const BatchSettings& settings, const BatchItem& item);

// The items of the settings' shard, in index order, triangles still 0. File names are
// `<template>_<index>`, the template's name made a safe file name (safe_file_name(),
// core/data_paths.h), the index zero-padded to the width of count - 1 (at least 4).
// Throws InputError for a count of 0, a bad jitter or a key_jitter key check_key_jitter()
// refuses.
std::vector<BatchItem> plan_batch(const BatchSettings& settings);

// How many items the settings' shard holds (0 for a bad shard), counted, not listed.
std::size_t shard_size(const BatchSettings& settings);

// The shard's cost before any of it is made or planned: shard_size() trees of the template,
// every one kept until the shard is written (tree/cost.h's many_trees_cost).
Cost estimate_batch_cost(const BatchSettings& settings);

// `manifest.json`, or `manifest_<I>of<N>.json` for a shard of more than one.
std::string manifest_file_name(const Shard& shard);

struct BatchResult {
    std::vector<BatchItem> items;
    std::vector<std::filesystem::path> files;  // every file written, the manifest last
};

// Generates the shard's trees and writes them and the manifest into `dir`, made (or refused
// with IoError naming it) before any tree is generated and removed again on failure
// (core/output_folder.h). Manifest: {"template", "count", "seed", "jitter", "shard": [I, N],
// "format", "jittered": [keys], "items": [{"index", "file", "seed", "parameters": {key: value},
// "triangles"}]}, where "parameters" are the jittered keys' values, key_jitter's last (with the
// template and `--set` they reproduce the tree: `sylva export -t T --seed SEED --set
// KEY=VALUE...`).
// Throws InputError, IoError, Cancelled; on any of them no file is left.
BatchResult run_batch(const BatchSettings& settings, const std::filesystem::path& dir);

}  // namespace sylva
