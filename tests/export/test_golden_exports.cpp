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
        {"oak.obj", 0x8d1e0940eb70af39ull},
        {"oak.glb", 0xcc8d3e6004fd3062ull},
        {"oak.ply", 0x81f3d549b72af374ull},
        {"oak.fbx", 0xa40344b44fa2b039ull},
        {"baobab.obj", 0x2a355982107f9e7eull},
        {"baobab.glb", 0x711bf3a511e4ba49ull},
        {"baobab.ply", 0xb2fd56d5d3f40390ull},
        {"baobab.fbx", 0x5c4627f23e171150ull},
        {"birch.obj", 0xe16f4f9015e84f10ull},
        {"birch.glb", 0x46cfa91c1d46117cull},
        {"birch.ply", 0x70eccc2ff7f7bfc0ull},
        {"birch.fbx", 0xfca8c07924041fb0ull},
        {"bush.obj", 0xc23aba323e1ed63full},
        {"bush.glb", 0xea139c05a0e90a4dull},
        {"bush.ply", 0xcf21521279229462ull},
        {"bush.fbx", 0x9c38979830353a8bull},
        {"cypress.obj", 0x6d6fda9fde623da7ull},
        {"cypress.glb", 0x1dc9b1f0cd060ef6ull},
        {"cypress.ply", 0xb09c1f232da13cf4ull},
        {"cypress.fbx", 0x84274915d684bd9aull},
        {"fir.obj", 0x78adb313abf3ca6cull},
        {"fir.glb", 0xa3d50743305da6a6ull},
        {"fir.ply", 0x97e4db6d45de48d8ull},
        {"fir.fbx", 0x6381511022f7ef32ull},
        {"honda.obj", 0x57647a64f01c3d49ull},
        {"honda.glb", 0xd44cbbbd3cfe76c0ull},
        {"honda.ply", 0xed1338fa8bfa1169ull},
        {"honda.fbx", 0x6018e1c9a6b1d690ull},
        {"palm.obj", 0x3118a170a23ddbecull},
        {"palm.glb", 0x20e936033b108610ull},
        {"palm.ply", 0xcccfcd5878ca4a84ull},
        {"palm.fbx", 0x4823187666bfb4dbull},
        {"pine.obj", 0xd2f7fe0e878f7910ull},
        {"pine.glb", 0xf9ef73b3254f1ad8ull},
        {"pine.ply", 0x8c978d7c0e7ce3ecull},
        {"pine.fbx", 0xfee8d5a0c6d2b365ull},
        {"spruce.obj", 0x254438c04e703111ull},
        {"spruce.glb", 0x28a1bde1cebbb55ull},
        {"spruce.ply", 0xe4e811c4dff70220ull},
        {"spruce.fbx", 0x2f1009efcb61874full},
        {"seed_spruce.obj", 0xc55c5e7c2e84f81ull},
        {"seed_spruce.glb", 0xd3dfcd95ba80f884ull},
        {"seed_spruce.ply", 0xbda4f717e1217704ull},
        {"seed_spruce.fbx", 0xb1b91d90c1231eb9ull},
        {"ternary.obj", 0x6b0472272ad26c72ull},
        {"ternary.glb", 0xa27d354ad296962ull},
        {"ternary.ply", 0x6c65074f76d48abull},
        {"ternary.fbx", 0x55246b6ecd7f040cull},
        {"willow.obj", 0x1219976725bf1f35ull},
        {"willow.glb", 0x5acaff9a4d581a31ull},
        {"willow.ply", 0xc12c72e828e0df91ull},
        {"willow.fbx", 0x64fa48593fb1f69cull},
        {"elm.obj", 0x35e71939fee621b5ull},
        {"elm.glb", 0x3f6129a6bb4d5f08ull},
        {"elm.ply", 0x94377452926cf2a6ull},
        {"elm.fbx", 0x9aae3b32a1b321aeull},
        {"maple.obj", 0x8374e16899a4b2abull},
        {"maple.glb", 0xcc57eec3560f018eull},
        {"maple.ply", 0xf811a24229a79c05ull},
        {"maple.fbx", 0xaa2828cdf7c44f44ull},
        {"hedge.obj", 0xbe47781fbd22fe25ull},
        {"hedge.glb", 0x9a0e6292eee4d17cull},
        {"hedge.ply", 0xa3052f2f74ac78bcull},
        {"hedge.fbx", 0x6719fdc05e74da0eull},
        {"windswept.obj", 0x853424113c7847e7ull},
        {"windswept.glb", 0x560aa02c2f16211cull},
        {"windswept.ply", 0x4a8ff18e4f0aa6b4ull},
        {"windswept.fbx", 0x99492e02ceaf5a61ull},
        // `export -t palm --lod -o palm_lod.glb`, `.fbx` and `... -o palm_lod.obj` (MTL,
        // LOD0-LOD3).
        {"palm_lod.glb", 0xb1dfbf9f2f276145ull},
        {"palm_lod.fbx", 0x6d6646c24e7ef8ull},
        {"palm_lod.obj", 0x9acff121824be286ull},
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
