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
        {"oak.obj", 0x696630d0ba13b3ddull},
        {"oak.glb", 0xbbce1b0a02d417eull},
        {"oak.ply", 0xed2085b63e47b98eull},
        {"oak.fbx", 0xbf6165808c640646ull},
        {"baobab.obj", 0x2a355982107f9e7eull},
        {"baobab.glb", 0x711bf3a511e4ba49ull},
        {"baobab.ply", 0xb2fd56d5d3f40390ull},
        {"baobab.fbx", 0x5c4627f23e171150ull},
        {"birch.obj", 0x2db88900d7fdbe3dull},
        {"birch.glb", 0xf359d0baf0083eafull},
        {"birch.ply", 0xce99169e632bdd88ull},
        {"birch.fbx", 0xe9473d7cdfd4fe6cull},
        {"bush.obj", 0xcf81afe98fb1628dull},
        {"bush.glb", 0x17844bd42e5ea4a9ull},
        {"bush.ply", 0xc94d01f8f29bc143ull},
        {"bush.fbx", 0xb2162afa9b7f7a96ull},
        {"cypress.obj", 0xf6923d3aef76ccadull},
        {"cypress.glb", 0x76bc3ecfec90c7d9ull},
        {"cypress.ply", 0xf367a3f5800e082cull},
        {"cypress.fbx", 0x51155e0343047903ull},
        {"fir.obj", 0x68f62c29325fd0fbull},
        {"fir.glb", 0x1b5a5991dfd1a2e1ull},
        {"fir.ply", 0xacddabad1fcfd39bull},
        {"fir.fbx", 0xe24c3d8190c55363ull},
        {"honda.obj", 0x5fc69e432c460922ull},
        {"honda.glb", 0x7928b7a75502e9abull},
        {"honda.ply", 0x4c8d268d275a3f19ull},
        {"honda.fbx", 0x8e2d34a48d73e3e4ull},
        {"palm.obj", 0x3118a170a23ddbecull},
        {"palm.glb", 0x20e936033b108610ull},
        {"palm.ply", 0xcccfcd5878ca4a84ull},
        {"palm.fbx", 0x4823187666bfb4dbull},
        {"pine.obj", 0x61785e3ef362147ull},
        {"pine.glb", 0x349e5991bfcf526cull},
        {"pine.ply", 0xabf1397517b380aull},
        {"pine.fbx", 0x32d27a301dd57c2aull},
        {"spruce.obj", 0x5e89ef6622236bc0ull},
        {"spruce.glb", 0x78f82c91482ae0fbull},
        {"spruce.ply", 0x602c29cb079a4ad9ull},
        {"spruce.fbx", 0xd6a981cc2b5c14ffull},
        {"seed_spruce.obj", 0xfd570bf52597f86bull},
        {"seed_spruce.glb", 0x2d46952199bea22aull},
        {"seed_spruce.ply", 0x60acb924b667084bull},
        {"seed_spruce.fbx", 0x9d5ac09347126118ull},
        {"ternary.obj", 0x4da7442070d1187bull},
        {"ternary.glb", 0x14730cc7cdaf014bull},
        {"ternary.ply", 0x455f85c68c08709dull},
        {"ternary.fbx", 0x6d93c2ae76e4d0faull},
        {"willow.obj", 0x67549071111c3956ull},
        {"willow.glb", 0xcc31ba4e69f4dca6ull},
        {"willow.ply", 0x818c51a7ee88c127ull},
        {"willow.fbx", 0xba4d312e193742e0ull},
        {"elm.obj", 0x2b316832c271b527ull},
        {"elm.glb", 0x67106c3b9df59a31ull},
        {"elm.ply", 0xf258a0d58f3e357aull},
        {"elm.fbx", 0x9e71358dbfcb711bull},
        {"maple.obj", 0x74d69fac8347eb6bull},
        {"maple.glb", 0x15cda3cf7dc05915ull},
        {"maple.ply", 0xe92611426c91d35aull},
        {"maple.fbx", 0x964dc4be228ac495ull},
        {"hedge.obj", 0x5c6d2674358100ebull},
        {"hedge.glb", 0xc9139620c9b4e651ull},
        {"hedge.ply", 0x596c1b3d5fde99c0ull},
        {"hedge.fbx", 0x7999c1099b910af5ull},
        {"windswept.obj", 0xf541715ef85dda41ull},
        {"windswept.glb", 0x39095c0abd63b903ull},
        {"windswept.ply", 0x6c98354e44dab82cull},
        {"windswept.fbx", 0x3b865a243f654d0full},
        // `export -t palm --lod -o palm_lod.glb`, `.fbx` and `... -o palm_lod.obj` (MTL,
        // LOD0-LOD3).
        {"palm_lod.glb", 0xabd5e8d03c768c4eull},
        {"palm_lod.fbx", 0x5e8de3eb944c3672ull},
        {"palm_lod.obj", 0x6f94009c68a33166ull},
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
