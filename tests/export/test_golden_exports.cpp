// Every built-in template exported as `sylva export -t NAME -o NAME.{obj,glb,ply,fbx}` does,
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
        {"oak.obj", 0x10e647e0becd128full},
        {"oak.glb", 0x75103913d2456a66ull},
        {"oak.ply", 0xef6e7a6ae99c686ull},
        {"oak.fbx", 0xc3baacdfd50d236dull},
        {"baobab.obj", 0x2a355982107f9e7eull},
        {"baobab.glb", 0xec3eaaa3dc07a1beull},
        {"baobab.ply", 0xb2fd56d5d3f40390ull},
        {"baobab.fbx", 0x7c1e9d86dcfa06afull},
        {"birch.obj", 0xe685a2c4b8c4d776ull},
        {"birch.glb", 0xec3ece65cc0bb166ull},
        {"birch.ply", 0xde8b3100ad63abdfull},
        {"birch.fbx", 0xca717cfabb72dcd0ull},
        {"bush.obj", 0xab33cee047e7c662ull},
        {"bush.glb", 0x7da5cda2239fcfa0ull},
        {"bush.ply", 0xa525bc0b046ed82aull},
        {"bush.fbx", 0xb80ee628a88ecc20ull},
        {"cypress.obj", 0xbd7972a6ce85b6f4ull},
        {"cypress.glb", 0x34ec6191b3177202ull},
        {"cypress.ply", 0xc7fe87da7b751720ull},
        {"cypress.fbx", 0xfce4b17489cbbaf5ull},
        {"fir.obj", 0xdcad3d7aed5662daull},
        {"fir.glb", 0x590af41076069964ull},
        {"fir.ply", 0x8ca71286c0e37404ull},
        {"fir.fbx", 0x7a55662ed2001fcdull},
        {"honda.obj", 0x3dc475e1d884b11cull},
        {"honda.glb", 0xea0d07ad51a84d80ull},
        {"honda.ply", 0xda717129afbfa2b7ull},
        {"honda.fbx", 0x55b2fc52492e647full},
        {"palm.obj", 0x8da9a7239350e3f9ull},
        {"palm.glb", 0x144206f23949e8a7ull},
        {"palm.ply", 0x6a2e3274e5168386ull},
        {"palm.fbx", 0xa50f283ad798e8eaull},
        {"pine.obj", 0xa47d46ee73fed45aull},
        {"pine.glb", 0x9362ec621f0a9fdull},
        {"pine.ply", 0xd5cc0961e3f4765eull},
        {"pine.fbx", 0xda93d56289fd1becull},
        {"spruce.obj", 0x49786b109b8bbb8eull},
        {"spruce.glb", 0xd2c61386f19240dcull},
        {"spruce.ply", 0x27c5030bcb47dc14ull},
        {"spruce.fbx", 0x5e87ddcd3696febeull},
        {"seed_spruce.obj", 0x623fa5b5645c3203ull},
        {"seed_spruce.glb", 0x17fd8dbfc19a52b0ull},
        {"seed_spruce.ply", 0x7b20facda484b2c6ull},
        {"seed_spruce.fbx", 0x43a8c723dba42a8full},
        {"ternary.obj", 0x6dc4d6971432f808ull},
        {"ternary.glb", 0x241bc92041b2127aull},
        {"ternary.ply", 0xe88d7e2fb67bf2adull},
        {"ternary.fbx", 0xaa31f74982bfed1dull},
        {"willow.obj", 0x3807b6b36cffad32ull},
        {"willow.glb", 0xb1c1301cec2705ccull},
        {"willow.ply", 0x9abcb31c89e00951ull},
        {"willow.fbx", 0x3b89e033224daf1dull},
        {"elm.obj", 0x6da6244b76a3c059ull},
        {"elm.glb", 0xc6cb3a786dc9fbeeull},
        {"elm.ply", 0xf176feacf39a2979ull},
        {"elm.fbx", 0x4a202a5e6f1c17edull},
        {"maple.obj", 0xd92b10557569bf46ull},
        {"maple.glb", 0x3bf5115bc30b6ae1ull},
        {"maple.ply", 0xba5a3b4ed4fb37f0ull},
        {"maple.fbx", 0xdd2cb5ac72a203d8ull},
        {"hedge.obj", 0x8ab248ac55dc3c74ull},
        {"hedge.glb", 0xb8789ae911db53f9ull},
        {"hedge.ply", 0xdbab7e0d2e1be068ull},
        {"hedge.fbx", 0x10203a817157352bull},
        {"windswept.obj", 0x80f2c210bf835d0dull},
        {"windswept.glb", 0x143898fee1daf2a1ull},
        {"windswept.ply", 0x480874fd469d9de5ull},
        {"windswept.fbx", 0xc58a7b0822c63111ull},
        // `export -t palm --lod -o palm_lod.glb`, `.fbx` and `... -o palm_lod.obj` (MTL,
        // LOD0-LOD3).
        {"palm_lod.glb", 0xfc96c7576ab36e7cull},
        {"palm_lod.fbx", 0x3b264bcc6cba3cebull},
        {"palm_lod.obj", 0x6f35896019f50498ull},
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
            ExportOptions options;  // as the CLI names the materials
            options.material_prefix = material_prefix(tmpl.name, tmpl.params.seed);
            std::vector<fs::path> files =
                write_tree(dir_ / key, tree, finished, tmpl.colors, options, format);
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
    EXPECT_EQ(checked_, golden_hashes().size() - 3) << "a template or a format went missing";
}

TEST_F(GoldenExports, LodChainsAreByteIdentical) {
    check(load_template("palm"), "palm_lod", true);
    EXPECT_EQ(checked_, 3u);
}

}  // namespace
}  // namespace sylva
