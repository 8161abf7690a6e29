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
        {"oak.obj", 0x46f3df16ba601c6bull},
        {"oak.glb", 0x16c55df7b7343a96ull},
        {"oak.ply", 0x81f3d549b72af374ull},
        {"baobab.obj", 0xcf18120094b91a4ull},
        {"baobab.glb", 0xe6786b3592dcf95dull},
        {"baobab.ply", 0xb2fd56d5d3f40390ull},
        {"birch.obj", 0x28bc95fc16dc5132ull},
        {"birch.glb", 0xf69d62ca40f4f915ull},
        {"birch.ply", 0x2b0ced62fdbc4031ull},
        {"bush.obj", 0xa24a00a75704cf47ull},
        {"bush.glb", 0xffe6dc1ea2a6e351ull},
        {"bush.ply", 0xcf21521279229462ull},
        {"cypress.obj", 0xfad876230b56f31dull},
        {"cypress.glb", 0x4bf0fdccf6d08aeull},
        {"cypress.ply", 0xb09c1f232da13cf4ull},
        {"fir.obj", 0xbd6f18c96d4be947ull},
        {"fir.glb", 0x8aabd1489cf90e6bull},
        {"fir.ply", 0xb614a72b9bf4887cull},
        {"honda.obj", 0xd3e14ae08ce2881dull},
        {"honda.glb", 0xaa97dcc174b15fa1ull},
        {"honda.ply", 0x56f5855ea06ba821ull},
        {"palm.obj", 0xdfe4776b0ce1400ull},
        {"palm.glb", 0x6097c9541bd37ff7ull},
        {"palm.ply", 0xcccfcd5878ca4a84ull},
        {"pine.obj", 0xa21bd0343ea58f48ull},
        {"pine.glb", 0x5b289b4226f9c55ull},
        {"pine.ply", 0x8c978d7c0e7ce3ecull},
        {"spruce.obj", 0xa54aa6aa6f9945dcull},
        {"spruce.glb", 0xc74e8ff2c4c0263dull},
        {"spruce.ply", 0xfe5fc31af73286f4ull},
        {"seed_spruce.obj", 0x4c7bb2d5190b208bull},
        {"seed_spruce.glb", 0xed73fc269834f6eeull},
        {"seed_spruce.ply", 0xbda4f717e1217704ull},
        {"ternary.obj", 0x2cae889a0f210f9cull},
        {"ternary.glb", 0x35079f92a484e6a6ull},
        {"ternary.ply", 0xdabca3c7cca4339bull},
        {"willow.obj", 0x97df37c833dbeef0ull},
        {"willow.glb", 0xf6de6d9485006070ull},
        {"willow.ply", 0x1be3654d7693c0e3ull},
        {"elm.obj", 0xe94825a8ab658328ull},
        {"elm.glb", 0x3535816047e6b285ull},
        {"elm.ply", 0x7714224328d676ddull},
        {"maple.obj", 0xff86cd1ccc24491ull},
        {"maple.glb", 0x5b79df20d8bd64aeull},
        {"maple.ply", 0xf811a24229a79c05ull},
        {"hedge.obj", 0x16c2fedeae45e755ull},
        {"hedge.glb", 0x7f97d6c3ff352364ull},
        {"hedge.ply", 0x74db3b54bd95c1e6ull},
        {"windswept.obj", 0x435b72877df04c90ull},
        {"windswept.glb", 0xb4bf0e7ab264e3feull},
        {"windswept.ply", 0x63cf295049be0977ull},
        // `export -t palm --lod -o palm_lod.glb` and `... -o palm_lod.obj` (MTL, LOD0-LOD3).
        {"palm_lod.glb", 0xc553a99660b2eacfull},
        {"palm_lod.obj", 0x1d10278c10cf666eull},
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
