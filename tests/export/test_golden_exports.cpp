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
        {"oak.obj", 0x3f7f097cf5b7d1c3ull},
        {"oak.glb", 0x86747ce0cfaa83f1ull},
        {"oak.ply", 0xbe8b060e65aac23aull},
        {"baobab.obj", 0xd85f64153e93c3d7ull},
        {"baobab.glb", 0xe3777e906615f5e8ull},
        {"baobab.ply", 0xbe534acc7e3e063dull},
        {"birch.obj", 0xc21c92aeb09c8a94ull},
        {"birch.glb", 0xbfd5e52ba218872ull},
        {"birch.ply", 0xb621cc62f17ac3ceull},
        {"bush.obj", 0x6e6327078a7c49a4ull},
        {"bush.glb", 0x862f1a3682b504d8ull},
        {"bush.ply", 0x8d3574398ce3264bull},
        {"cypress.obj", 0xc95df5c0e3c66ddaull},
        {"cypress.glb", 0x5749dd10d5f72287ull},
        {"cypress.ply", 0xc7fe87da7b751720ull},
        {"fir.obj", 0x9492592c0e13d40cull},
        {"fir.glb", 0x7ce130e66eff95bdull},
        {"fir.ply", 0x87be7c604349218dull},
        {"honda.obj", 0x9c95872be9c3af9cull},
        {"honda.glb", 0xf0c667183b35f6a1ull},
        {"honda.ply", 0x1206c08ebac4a5a5ull},
        {"palm.obj", 0xab8097f16f190e30ull},
        {"palm.glb", 0xf1b14d621b3c4056ull},
        {"palm.ply", 0xce2d11bedd8aa616ull},
        {"pine.obj", 0x5c9560eccac57da6ull},
        {"pine.glb", 0x9b5fd81cd1038205ull},
        {"pine.ply", 0x9c523e5b011fe860ull},
        {"spruce.obj", 0x6e03f5e7f412feb2ull},
        {"spruce.glb", 0x3408802b8da7568dull},
        {"spruce.ply", 0xf1513598074ee50dull},
        {"seed_spruce.obj", 0xd34364504f77cdf8ull},
        {"seed_spruce.glb", 0x9f6b817d0ee24947ull},
        {"seed_spruce.ply", 0xa170fd64650696f1ull},
        {"ternary.obj", 0xdb8fc8ac30514f54ull},
        {"ternary.glb", 0xd95d6af008688514ull},
        {"ternary.ply", 0xad5d6423c2adc3b4ull},
        {"willow.obj", 0xc21fe93816966b23ull},
        {"willow.glb", 0x12c4273cecde4f32ull},
        {"willow.ply", 0x215dadc47612ba20ull},
        {"elm.obj", 0x9e60105b25e9d5eull},
        {"elm.glb", 0x37b31924941507e1ull},
        {"elm.ply", 0xe5e5bc652b8e94d1ull},
        {"maple.obj", 0x76f600c7b02ab58bull},
        {"maple.glb", 0x8786a872fd90c9dull},
        {"maple.ply", 0xb26838232d53c2c1ull},
        {"hedge.obj", 0x3b63be4748193bf3ull},
        {"hedge.glb", 0x33608ff756eefbefull},
        {"hedge.ply", 0x1a694f9e4e31b511ull},
        {"windswept.obj", 0xfdf926a7cb142e15ull},
        {"windswept.glb", 0x60c0c98bf546a095ull},
        {"windswept.ply", 0x8bc78163b0372ebbull},
        // `export -t palm --lod -o palm_lod.glb` and `... -o palm_lod.obj` (MTL, LOD0-LOD3).
        {"palm_lod.glb", 0x5763e4ca24927962ull},
        {"palm_lod.obj", 0x8cc98078c0547814ull},
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
