// sylva batch: variants that differ, a manifest that describes them, shards that add up to
// the whole batch byte for byte, and the same bytes for the same seed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/errors.h"
#include "core/random.h"
#include "core/seed.h"
#include "forest/batch.h"
#include "forest/variation.h"
#include "tests/helpers.h"
#include "tree/grammar_constants.h"
#include "tree/parameters.h"
#include "tree/template_library.h"
#include "turtle/lsystem_params.h"

namespace {

namespace fs = std::filesystem;
using namespace sylva;

std::map<std::string, std::string> files_in(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(dir))
        files[entry.path().filename().string()] = test::read_file(entry.path());
    return files;
}

// A small, fast batch: the spruce at a low budget.
BatchSettings small_batch(std::size_t count) {
    BatchSettings s;
    s.tree = load_template("spruce");
    s.count = count;
    s.seed = 7;
    s.jitter = 0.2;
    s.finish.budget.total = 200;
    return s;
}

class Batch : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sylva_batch_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

// A variant's seed is the top 53 bits of a splitmix64 output: distinct, and a seed of the
// one range (core/seed.h) whatever the base, so a saved variant always reopens.
TEST(Variation, SeedsAreSplitmixOutputsWithinTheSeedRangeAndDistinct) {
    Random r(42);
    for (std::uint64_t i = 0; i < 5; ++i) EXPECT_EQ(variant_seed(42, i), r.next() >> 11);
    EXPECT_NE(variant_seed(42, 0), variant_seed(43, 0));
    std::uint64_t largest = 0;
    for (const std::uint64_t base : {std::uint64_t{0}, std::uint64_t{1}, ~std::uint64_t{0}})
        for (std::uint64_t i = 0; i < 4096; ++i) {
            EXPECT_LE(variant_seed(base, i), kMaxSeed);
            largest = std::max(largest, variant_seed(base, i));
        }
    EXPECT_GT(largest, kMaxSeed / 2);  // the whole range is used, not a corner of it
}

TEST(Variation, JitterStaysInRangeAndVaries) {
    const TreeParams base = load_template("oak").params;
    const TreeParams a = varied_params(base, 1, 0.3), b = varied_params(base, 2, 0.3);
    bool differs = false;
    for (const ParamInfo& info : param_infos()) {
        const double value = *get_param(a, info.key);
        EXPECT_GE(value, info.min) << info.key;
        EXPECT_LE(value, info.max) << info.key;
        differs |= value != *get_param(b, info.key);
    }
    EXPECT_TRUE(differs);
    auto length = [](const TreeParams& p) { return lsystem_params(p).branch_length; };
    EXPECT_EQ(length(varied_params(base, 1, 0.3)), length(a));  // deterministic
    EXPECT_EQ(length(varied_params(base, 5, 0.0)), length(base));
    EXPECT_THROW(varied_params(base, 1, 1.5), InputError);
}

// `--jitter a=0.3`: a #define varies within its comment's range, whole where the range is,
// each key from a stream of its own (adding a key leaves the others' values).
TEST(Variation, KeyJitterVariesGrammarConstantsWithinTheirRanges) {
    const TreeTemplate oak = load_template("oak");  // a 46 [20, 75], s 0.8 [0.6, 0.95]
    const std::vector<KeyJitter> keys = {{"a", 1.0}, {"s", 1.0}};
    std::vector<double> as;
    for (std::uint64_t seed = 0; seed < 64; ++seed) {
        const auto values = varied_keys(oak, seed, keys);
        ASSERT_EQ(values.size(), 2u);
        EXPECT_EQ(values[0].first, "a");
        EXPECT_GE(values[0].second, 20.0);
        EXPECT_LE(values[0].second, 75.0);
        EXPECT_EQ(values[0].second, std::round(values[0].second));
        EXPECT_GE(values[1].second, 0.6);
        EXPECT_LE(values[1].second, 0.95);
        EXPECT_EQ(varied_keys(oak, seed, std::vector<KeyJitter>{{"s", 1.0}})[0].second,
                  values[1].second);
        as.push_back(values[0].second);
    }
    EXPECT_GT(*std::max_element(as.begin(), as.end()) - *std::min_element(as.begin(), as.end()),
              20.0);
    const std::vector<KeyJitter> none = {{"a", 0.0}};
    EXPECT_EQ(varied_keys(oak, 3, none)[0].second, 46.0);

    for (const KeyJitter& bad :
         std::vector<KeyJitter>{{"zz", 0.1}, {"a", 1.5}, {"leaf_shape", 0.1}, {"crown_merge", 0.1}})
        EXPECT_THROW(check_key_jitter(oak, std::vector<KeyJitter>{bad}), InputError) << bad.key;
    TreeTemplate expression = oak;
    expression.grammar = "#define x (a*2) # [0, 200] twice\n" + oak.grammar;
    EXPECT_THROW(check_key_jitter(expression, std::vector<KeyJitter>{{"x", 0.1}}), InputError);
}

TEST(Variation, ParseShard) {
    EXPECT_EQ(parse_shard("2/4").index, 1u);
    EXPECT_EQ(parse_shard("2/4").count, 4u);
    for (const char* bad : {"0/4", "5/4", "1", "a/b", "1/0", "/3", "2/"})
        EXPECT_THROW(parse_shard(bad), InputError) << bad;
}

TEST_F(Batch, WritesDistinctVariantsAndAManifest) {
    const BatchResult result = run_batch(small_batch(3), dir_);
    ASSERT_EQ(result.items.size(), 3u);
    const auto files = files_in(dir_);
    ASSERT_EQ(files.size(), 4u);  // 3 trees + manifest
    EXPECT_NE(files.at("spruce_0000.glb"), files.at("spruce_0001.glb"));
    EXPECT_NE(files.at("spruce_0001.glb"), files.at("spruce_0002.glb"));
    const nlohmann::json manifest = nlohmann::json::parse(files.at("manifest.json"));
    ASSERT_EQ(manifest["items"].size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        const auto& item = manifest["items"][i];
        EXPECT_EQ(item["index"], i);
        EXPECT_EQ(item["seed"].get<std::uint64_t>(), variant_seed(7, i));
        EXPECT_TRUE(files.count(item["file"].get<std::string>()));
        EXPECT_GT(item["triangles"].get<std::size_t>(), 100u);
        EXPECT_EQ(item["parameters"]["branch_length"].get<double>(),
                  lsystem_params(result.items[i].params).branch_length);
    }
}

// A template's name is data from a stranger: the batch's files stay in the folder.
TEST_F(Batch, ATemplateNameCannotLeadOutOfTheFolder) {
    for (const char* name : {"../../../escaped", "/tmp/absolute", "..", "a/b"}) {
        BatchSettings settings = small_batch(1);
        settings.tree.name = name;
        const fs::path dir = dir_ / "out";
        const BatchResult result = run_batch(settings, dir);
        ASSERT_EQ(result.items.size(), 1u);
        const fs::path file = result.items[0].file;
        EXPECT_EQ(file.filename(), file) << name << " -> " << file;
        EXPECT_TRUE(fs::is_regular_file(dir / file)) << name << " -> " << file;
        std::size_t entries = 0;
        for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
            if (entry.path() == dir) continue;
            ++entries;
            EXPECT_EQ(entry.path().parent_path(), dir) << entry.path();
        }
        EXPECT_EQ(entries, 2u);  // the tree and the manifest
        fs::remove_all(dir_);
    }
    EXPECT_FALSE(fs::exists(dir_.parent_path() / "escaped_0000.glb"));
}

// The manifest lists the jittered #define with each item's value, and that value is in the
// rules the item was grown from.
TEST_F(Batch, KeyJitterGoesIntoTheTreesAndTheManifest) {
    BatchSettings settings = small_batch(2);
    settings.key_jitter = {{"g", 0.5}};
    const BatchResult result = run_batch(settings, dir_);
    const nlohmann::json manifest = nlohmann::json::parse(files_in(dir_).at("manifest.json"));
    EXPECT_EQ(manifest["jittered"].back(), "g");
    for (std::size_t i = 0; i < 2; ++i) {
        const double d = manifest["items"][i]["parameters"]["g"].get<double>();
        EXPECT_EQ(d, result.items[i].keys.at(0).second);
        EXPECT_EQ(find_grammar_define(item_template(settings, result.items[i]).grammar, "g")->value,
                  d);
    }
}

TEST_F(Batch, SameSeedSameBytes) {
    run_batch(small_batch(2), dir_ / "a");
    run_batch(small_batch(2), dir_ / "b");
    EXPECT_EQ(files_in(dir_ / "a"), files_in(dir_ / "b"));
}

// The union of shards 1/4..4/4 is the unsharded batch: same tree files, byte for byte, and
// the shard manifests' items are the whole manifest's items.
TEST_F(Batch, FourShardsMakeTheWholeBatch) {
    const std::size_t count = 6;
    run_batch(small_batch(count), dir_ / "whole");
    std::map<std::string, std::string> shards;
    nlohmann::json items = nlohmann::json::array();
    for (std::size_t i = 0; i < 4; ++i) {
        BatchSettings s = small_batch(count);
        s.shard = {i, 4};
        run_batch(s, dir_ / "shards");
    }
    for (std::size_t i = 0; i < 4; ++i) {
        const nlohmann::json m =
            nlohmann::json::parse(test::read_file(dir_ / "shards" / manifest_file_name({i, 4})));
        for (const auto& item : m["items"]) items.push_back(item);
        fs::remove(dir_ / "shards" / manifest_file_name({i, 4}));
    }
    auto whole = files_in(dir_ / "whole");
    const nlohmann::json manifest = nlohmann::json::parse(whole.at("manifest.json"));
    whole.erase("manifest.json");
    EXPECT_EQ(files_in(dir_ / "shards"), whole);
    std::sort(items.begin(), items.end(),
              [](const auto& a, const auto& b) { return a["index"] < b["index"]; });
    EXPECT_EQ(items, manifest["items"]);
}

TEST_F(Batch, AFailedBatchLeavesNoFile) {
    fs::create_directories(dir_);
    fs::create_directories(dir_ / "spruce_0001.glb");  // a directory where a tree goes
    EXPECT_THROW(run_batch(small_batch(3), dir_), IoError);
    EXPECT_FALSE(fs::exists(dir_ / "spruce_0000.glb"));
    EXPECT_FALSE(fs::exists(dir_ / "manifest.json"));
}

}  // namespace
