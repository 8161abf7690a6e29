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
        {"oak.obj", 0x85fe6697268f0904ull},
        {"oak.glb", 0x3d7815770a03bab3ull},
        {"oak.ply", 0x4fbed04f8bd621a0ull},
        {"oak.fbx", 0x6226e7234dba3520ull},
        {"baobab.obj", 0x2a355982107f9e7eull},
        {"baobab.glb", 0x711bf3a511e4ba49ull},
        {"baobab.ply", 0xb2fd56d5d3f40390ull},
        {"baobab.fbx", 0x5c4627f23e171150ull},
        {"birch.obj", 0xa1ac98ccb37f0cfaull},
        {"birch.glb", 0x5a8f66bf72a497b8ull},
        {"birch.ply", 0xe76a8689f185593ull},
        {"birch.fbx", 0x9d8d99fb4a1a046bull},
        {"bush.obj", 0x8f7c1cf1064dd898ull},
        {"bush.glb", 0x67dea3431b676bfeull},
        {"bush.ply", 0xb7f16734d063143ull},
        {"bush.fbx", 0xbd1cc45ba237e2acull},
        {"cypress.obj", 0x964e880af127b09eull},
        {"cypress.glb", 0x81db1aa41cdcb9bdull},
        {"cypress.ply", 0x8ada96cc396bbd91ull},
        {"cypress.fbx", 0xf664514518547d3full},
        {"fir.obj", 0x4ad0535334db70c3ull},
        {"fir.glb", 0x827d5e0b34030579ull},
        {"fir.ply", 0xd790d87bc6ce61c4ull},
        {"fir.fbx", 0xb896154756beefbull},
        {"honda.obj", 0xf6e018462ca08f46ull},
        {"honda.glb", 0xa326d5ff24800b87ull},
        {"honda.ply", 0x8e687123916a0b4full},
        {"honda.fbx", 0x63cb8870e831a370ull},
        {"palm.obj", 0xbc8122dbb720984dull},
        {"palm.glb", 0x57c48e02cbe96beeull},
        {"palm.ply", 0x70f3211cd196262full},
        {"palm.fbx", 0xb3f32ee7c9c056bfull},
        {"pine.obj", 0xb84f81aa9c6ffe45ull},
        {"pine.glb", 0x2b4d0bdafa05e989ull},
        {"pine.ply", 0x370e712a4391b224ull},
        {"pine.fbx", 0x4aa17952033671e4ull},
        {"spruce.obj", 0x5266b79dd0b6ce4eull},
        {"spruce.glb", 0xb8d2e785095e9670ull},
        {"spruce.ply", 0xf3e7f551c684ff66ull},
        {"spruce.fbx", 0xca99e3a4a90600b4ull},
        {"seed_spruce.obj", 0xb76b3d7c51fd5525ull},
        {"seed_spruce.glb", 0xfb66e75e2670b26ull},
        {"seed_spruce.ply", 0x16e36605fa19d3efull},
        {"seed_spruce.fbx", 0x80567e5d2dbbfe1full},
        {"ternary.obj", 0x47e3aa3d2841e341ull},
        {"ternary.glb", 0x88c0c2957a84a8a6ull},
        {"ternary.ply", 0x7a813c7df0d423abull},
        {"ternary.fbx", 0x2e37ffa489828a87ull},
        {"willow.obj", 0x18295651ba1acea6ull},
        {"willow.glb", 0x3d7013994fe22bd4ull},
        {"willow.ply", 0x64f5421028b46293ull},
        {"willow.fbx", 0x371ccd92cf6059dfull},
        {"elm.obj", 0xfcf62520cb1ff78dull},
        {"elm.glb", 0x87c9b812bdfab6e7ull},
        {"elm.ply", 0xb33164e9ae58f5aull},
        {"elm.fbx", 0x7ea36ea53cb8d926ull},
        {"maple.obj", 0xb02e0dad01fe75b3ull},
        {"maple.glb", 0xd44033e4f96ea4beull},
        {"maple.ply", 0xfba53d44bd6e8e23ull},
        {"maple.fbx", 0xc50a4dd2b3d56c30ull},
        {"hedge.obj", 0x154d6339783696caull},
        {"hedge.glb", 0xfd5916cc70508f5aull},
        {"hedge.ply", 0xb9e45b42f24f0ef3ull},
        {"hedge.fbx", 0x12a048c293ac024bull},
        {"windswept.obj", 0x3d5be6e7518557f5ull},
        {"windswept.glb", 0x922a55996f90ed1full},
        {"windswept.ply", 0x8487abf617d0ccaull},
        {"windswept.fbx", 0x30efdcb89ac5015dull},
        // `export -t palm --lod -o palm_lod.glb`, `.fbx` and `... -o palm_lod.obj` (MTL,
        // LOD0-LOD3).
        {"palm_lod.glb", 0x627c2e5951040cd1ull},
        {"palm_lod.fbx", 0x8e8740138a2d9ae4ull},
        {"palm_lod.obj", 0xbfd9ec93b3091306ull},
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
