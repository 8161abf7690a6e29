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
        {"oak.obj", 0x253d47eefd915c14ull},
        {"oak.glb", 0xb094a4a79b326a5bull},
        {"oak.ply", 0xac4c9707511e1440ull},
        {"oak.fbx", 0x135b5204f9a3c866ull},
        {"baobab.obj", 0x2a355982107f9e7eull},
        {"baobab.glb", 0x711bf3a511e4ba49ull},
        {"baobab.ply", 0xb2fd56d5d3f40390ull},
        {"baobab.fbx", 0x5c4627f23e171150ull},
        {"birch.obj", 0x94f9549b671a9159ull},
        {"birch.glb", 0xb8456a62d82cacbaull},
        {"birch.ply", 0xe53370e9596c8ea7ull},
        {"birch.fbx", 0xc54e8c1fc0655ef5ull},
        {"bush.obj", 0x8f7c1cf1064dd898ull},
        {"bush.glb", 0x67dea3431b676bfeull},
        {"bush.ply", 0xb7f16734d063143ull},
        {"bush.fbx", 0xbd1cc45ba237e2acull},
        {"cypress.obj", 0xd5128349ebf1e487ull},
        {"cypress.glb", 0x58158dbd264b0cd5ull},
        {"cypress.ply", 0xed30d11f55da27ebull},
        {"cypress.fbx", 0x130e875ef7021377ull},
        {"fir.obj", 0x4ad0535334db70c3ull},
        {"fir.glb", 0x7591f903666e834cull},
        {"fir.ply", 0xd790d87bc6ce61c4ull},
        {"fir.fbx", 0xba822686abf57162ull},
        {"honda.obj", 0xf6e018462ca08f46ull},
        {"honda.glb", 0xb28d836664af9147ull},
        {"honda.ply", 0x8e687123916a0b4full},
        {"honda.fbx", 0xbe98ee239c4ac977ull},
        {"palm.obj", 0x9473ecca6a9b5b60ull},
        {"palm.glb", 0xa93ddab89d235d8eull},
        {"palm.ply", 0x1732326e42d040b0ull},
        {"palm.fbx", 0x88434f2ff7782a2aull},
        {"pine.obj", 0xe70a5319624feccbull},
        {"pine.glb", 0xc58424fa1f13cc6eull},
        {"pine.ply", 0x6d366722729d72ffull},
        {"pine.fbx", 0x8e987e42eaa13d85ull},
        {"spruce.obj", 0x5266b79dd0b6ce4eull},
        {"spruce.glb", 0xa13e0a9d6cac4034ull},
        {"spruce.ply", 0xf3e7f551c684ff66ull},
        {"spruce.fbx", 0x5b6f4c5764bba3e6ull},
        {"seed_spruce.obj", 0x30373fc9ee72b9f6ull},
        {"seed_spruce.glb", 0x4ec54af725e2ee30ull},
        {"seed_spruce.ply", 0x35020357c9a50dc5ull},
        {"seed_spruce.fbx", 0xc186ac5a7b644801ull},
        {"ternary.obj", 0xfef3ddcd7936e257ull},
        {"ternary.glb", 0xdffe08f4272a98f1ull},
        {"ternary.ply", 0x4bf2363e11a62867ull},
        {"ternary.fbx", 0xa3f7fc95bd65de00ull},
        {"willow.obj", 0x2cf97ddf47b6ebecull},
        {"willow.glb", 0x7a6b9f2fbf7c3ffaull},
        {"willow.ply", 0xe5bb161d1f81c737ull},
        {"willow.fbx", 0x43a2c6463cc0734bull},
        {"elm.obj", 0x11af5fbded336ce9ull},
        {"elm.glb", 0xcd13aed14bbee962ull},
        {"elm.ply", 0x12d6645c69c1c3eull},
        {"elm.fbx", 0xa51ac9be13c58f2full},
        {"maple.obj", 0xc075b57e31762c5cull},
        {"maple.glb", 0x96780cd9c5e2c7fdull},
        {"maple.ply", 0x3dc1181359f28970ull},
        {"maple.fbx", 0x3a79e68d5cc09e9eull},
        {"hedge.obj", 0x62175f6e76d9042bull},
        {"hedge.glb", 0xf613af3f93c4ba7bull},
        {"hedge.ply", 0xad8b0052a4e8199dull},
        {"hedge.fbx", 0xf2888f4947d742dcull},
        {"windswept.obj", 0x13a9bed722d37110ull},
        {"windswept.glb", 0x4361726f89820be1ull},
        {"windswept.ply", 0x8febc03724025c77ull},
        {"windswept.fbx", 0x59e8f7b385e7c876ull},
        // `export -t palm --lod -o palm_lod.glb`, `.fbx` and `... -o palm_lod.obj` (MTL,
        // LOD0-LOD3).
        {"palm_lod.glb", 0xe0490a3d44f163f0ull},
        {"palm_lod.fbx", 0xaed1e15d35b0bc00ull},
        {"palm_lod.obj", 0xfc4d7105b788bd60ull},
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
            options.engine.wind_motion = wind_motion(tmpl.params);
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
