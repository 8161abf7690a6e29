// Every built-in template exported as `sylva export -t NAME -o NAME.{obj,glb,ply}` does,
// hashed byte for byte against the recorded files.
// A change here must be on purpose: update the hash and say why in the commit body.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "export/export_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

struct Golden {
    const char* file;  // relative to the export's folder; an OBJ's .mtl is hashed after it
    std::uint64_t fnv1a;
};

// FNV-1a 64 over the files' bytes, one after the other.
std::uint64_t fnv1a(const std::vector<fs::path>& files) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const fs::path& file : files) {
        std::ifstream in(file, std::ios::binary);
        for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) {
            h ^= static_cast<unsigned char>(*it);
            h *= 0x100000001b3ull;
        }
    }
    return h;
}

const std::map<std::string, std::uint64_t>& golden_hashes() {
    static const std::map<std::string, std::uint64_t> hashes = {
        {"oak.obj", 0x8de52ec84074b8d5ull},
        {"oak.glb", 0x8f3cba0181e78e2bull},
        {"oak.ply", 0xef6e7a6ae99c686ull},
        {"baobab.obj", 0xcf18120094b91a4ull},
        {"baobab.glb", 0xe6786b3592dcf95dull},
        {"baobab.ply", 0xb2fd56d5d3f40390ull},
        {"birch.obj", 0x712385621b7869f4ull},
        {"birch.glb", 0xf6850fcff1654482ull},
        {"birch.ply", 0xde8b3100ad63abdfull},
        {"bush.obj", 0x2253432c1b745fb2ull},
        {"bush.glb", 0x552450fac86321cfull},
        {"bush.ply", 0xa525bc0b046ed82aull},
        {"cypress.obj", 0xc95df5c0e3c66ddaull},
        {"cypress.glb", 0x5749dd10d5f72287ull},
        {"cypress.ply", 0xc7fe87da7b751720ull},
        {"fir.obj", 0x447002f21ddad9c8ull},
        {"fir.glb", 0x86ed5ff96b024c29ull},
        {"fir.ply", 0x8ca71286c0e37404ull},
        {"honda.obj", 0x4331fd0ff95b4c64ull},
        {"honda.glb", 0x936d9c5db821f533ull},
        {"honda.ply", 0xda717129afbfa2b7ull},
        {"palm.obj", 0xa84e39a2b95cb95ull},
        {"palm.glb", 0x5f8a65716567f9c7ull},
        {"palm.ply", 0x6a2e3274e5168386ull},
        {"pine.obj", 0xb37f01558f601a62ull},
        {"pine.glb", 0x827b27c4e5e153a1ull},
        {"pine.ply", 0xd5cc0961e3f4765eull},
        {"spruce.obj", 0x8bb17d6279beacbeull},
        {"spruce.glb", 0xaa69cbc437721a54ull},
        {"spruce.ply", 0x27c5030bcb47dc14ull},
        {"seed_spruce.obj", 0xf7b2ab9e280ff2bull},
        {"seed_spruce.glb", 0x90d08d11d961a07aull},
        {"seed_spruce.ply", 0x7b20facda484b2c6ull},
        {"ternary.obj", 0xf3d5c0fd3895d1beull},
        {"ternary.glb", 0xdcd110ef3efbde53ull},
        {"ternary.ply", 0xe88d7e2fb67bf2adull},
        {"willow.obj", 0xd005d3c0e8dfa43eull},
        {"willow.glb", 0x95d7e3b8890d5000ull},
        {"willow.ply", 0x9abcb31c89e00951ull},
        {"elm.obj", 0x7ee691b705a419d1ull},
        {"elm.glb", 0xfa0648d790157226ull},
        {"elm.ply", 0xf176feacf39a2979ull},
        {"maple.obj", 0xd7e9107db5bf855eull},
        {"maple.glb", 0x610a668931004ac6ull},
        {"maple.ply", 0xba5a3b4ed4fb37f0ull},
        {"hedge.obj", 0xd6377fb9f4bd2440ull},
        {"hedge.glb", 0x6e0d2e09b2ebb3bull},
        {"hedge.ply", 0xdbab7e0d2e1be068ull},
        {"windswept.obj", 0xba7169e225536245ull},
        {"windswept.glb", 0x36c2b48f1b594537ull},
        {"windswept.ply", 0x480874fd469d9de5ull},
        // `export -t palm --lod -o palm_lod.glb` and `... -o palm_lod.obj` (MTL, LOD0-LOD3).
        {"palm_lod.glb", 0xf79c39e4ef83888cull},
        {"palm_lod.obj", 0x6f9e90343d44023cull},
    };
    return hashes;
}

class GoldenExports : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sylva_golden_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Writes `name` + ext for each extension the way the CLI does, and checks the hashes.
    void check(const TreeTemplate& tmpl, const std::string& name, bool lod) {
        FinishSettings finish;
        finish.budget.total = static_cast<std::size_t>(tmpl.params.triangle_budget);
        finish.lod = lod;
        MeshOptions mesh;
        mesh.budget = game_budget(finish);
        const Tree tree = generate_tree(tmpl, mesh);
        const FinishedTree finished = finish_tree(tree, finish);
        for (const ExportFormat* format : export_formats()) {
            const std::string key = name + std::string(format->extension);
            const auto expected = golden_hashes().find(key);
            if (expected == golden_hashes().end()) continue;
            std::vector<fs::path> files = write_tree(dir_ / key, tree, finished, tmpl.colors);
            // The order the hashes were taken in: an OBJ before its MTL, a chain's MTL
            // before its levels.
            std::stable_partition(files.begin(), files.end(), [lod](const fs::path& f) {
                return (f.extension() == ".mtl") == lod;
            });
            ++checked_;
            const std::uint64_t hash = fnv1a(files);
            EXPECT_EQ(hash, expected->second)
                << key << " (now 0x" << std::hex << hash << std::dec << ")"
                << " is no longer byte-identical to the recorded export";
        }
    }

    fs::path dir_;
    std::size_t checked_ = 0;
};

TEST_F(GoldenExports, EveryTemplateInEveryFormatIsByteIdentical) {
    for (const TreeTemplate* tmpl : builtin_templates()) check(*tmpl, tmpl->name, false);
    EXPECT_EQ(checked_, golden_hashes().size() - 2) << "a template or a format went missing";
}

TEST_F(GoldenExports, LodChainsAreByteIdentical) {
    check(load_template("palm"), "palm_lod", true);
    EXPECT_EQ(checked_, 2u);
}

}  // namespace
}  // namespace sylva
