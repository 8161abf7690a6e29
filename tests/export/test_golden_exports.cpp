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
        {"oak.glb", 0x68684065e8cf883ull},
        {"oak.ply", 0xed2085b63e47b98eull},
        {"oak.fbx", 0xa58364397f54e75bull},
        {"baobab.obj", 0x2a355982107f9e7eull},
        {"baobab.glb", 0xec3eaaa3dc07a1beull},
        {"baobab.ply", 0xb2fd56d5d3f40390ull},
        {"baobab.fbx", 0x7c1e9d86dcfa06afull},
        {"birch.obj", 0x2db88900d7fdbe3dull},
        {"birch.glb", 0x502274891dba7e02ull},
        {"birch.ply", 0xce99169e632bdd88ull},
        {"birch.fbx", 0x18fe89e55849d364ull},
        {"bush.obj", 0xcf81afe98fb1628dull},
        {"bush.glb", 0x37bbebe9d75e740aull},
        {"bush.ply", 0xc94d01f8f29bc143ull},
        {"bush.fbx", 0x67c0d43b6e021758ull},
        {"cypress.obj", 0xf6923d3aef76ccadull},
        {"cypress.glb", 0xf15b8005b9361d18ull},
        {"cypress.ply", 0xf367a3f5800e082cull},
        {"cypress.fbx", 0x6ced3cee47be34a2ull},
        {"fir.obj", 0x68f62c29325fd0fbull},
        {"fir.glb", 0x755c24d3cbd1365aull},
        {"fir.ply", 0xacddabad1fcfd39bull},
        {"fir.fbx", 0x89e5f171fb29883aull},
        {"honda.obj", 0x5fc69e432c460922ull},
        {"honda.glb", 0x35b1134be984c680ull},
        {"honda.ply", 0x4c8d268d275a3f19ull},
        {"honda.fbx", 0xa5a986a3241e8134ull},
        {"palm.obj", 0x3118a170a23ddbecull},
        {"palm.glb", 0x86aff694b464984bull},
        {"palm.ply", 0xcccfcd5878ca4a84ull},
        {"palm.fbx", 0xd8e10d9bea45c89full},
        {"pine.obj", 0x61785e3ef362147ull},
        {"pine.glb", 0x705d32a2b1ccbf7dull},
        {"pine.ply", 0xabf1397517b380aull},
        {"pine.fbx", 0xe3bc7f9e46ca55full},
        {"spruce.obj", 0x5e89ef6622236bc0ull},
        {"spruce.glb", 0x71fffb2371c87cd0ull},
        {"spruce.ply", 0x602c29cb079a4ad9ull},
        {"spruce.fbx", 0xdb2065e4ea380816ull},
        {"seed_spruce.obj", 0xfd570bf52597f86bull},
        {"seed_spruce.glb", 0xafecefd42e32cf8aull},
        {"seed_spruce.ply", 0x60acb924b667084bull},
        {"seed_spruce.fbx", 0xfba5ab49c559d95eull},
        {"ternary.obj", 0x4da7442070d1187bull},
        {"ternary.glb", 0x77e2566588604ecull},
        {"ternary.ply", 0x455f85c68c08709dull},
        {"ternary.fbx", 0x92c51e66c50da1bull},
        {"willow.obj", 0x67549071111c3956ull},
        {"willow.glb", 0xa30f6814feb7a071ull},
        {"willow.ply", 0x818c51a7ee88c127ull},
        {"willow.fbx", 0x988917672f42acf5ull},
        {"elm.obj", 0x2b316832c271b527ull},
        {"elm.glb", 0xcd7a9949590b9844ull},
        {"elm.ply", 0xf258a0d58f3e357aull},
        {"elm.fbx", 0xd44aa7f57c0ce29dull},
        {"maple.obj", 0x74d69fac8347eb6bull},
        {"maple.glb", 0x774c095315ff1bf4ull},
        {"maple.ply", 0xe92611426c91d35aull},
        {"maple.fbx", 0xf9c4bc3462279725ull},
        {"hedge.obj", 0x5c6d2674358100ebull},
        {"hedge.glb", 0xe7ec7c70b319f743ull},
        {"hedge.ply", 0x596c1b3d5fde99c0ull},
        {"hedge.fbx", 0x777e2d56a76c12faull},
        {"windswept.obj", 0xf541715ef85dda41ull},
        {"windswept.glb", 0xde9ce7f7fcd19ff4ull},
        {"windswept.ply", 0x6c98354e44dab82cull},
        {"windswept.fbx", 0xe8699810d2a15f27ull},
        // `export -t palm --lod -o palm_lod.glb`, `.fbx` and `... -o palm_lod.obj` (MTL,
        // LOD0-LOD3).
        {"palm_lod.glb", 0xb4c63630272ecd52ull},
        {"palm_lod.fbx", 0x8b63b39f3d33a6cdull},
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
