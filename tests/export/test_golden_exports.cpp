// Every built-in template exported as `sylva export -t NAME -o NAME.{obj,glb,ply}` does,
// hashed byte for byte against the files the release before the re-cut (issue 10) wrote.
// A change here must be on purpose: update the hash and say why in the commit.
// Changed on purpose by "the game mesh in milliseconds" (leaves and LODs): leaves written
// once (one-sided), leaves thinned to the leaf budget, LOD chains reduced level from level,
// pinned to the ground, with one _LOD suffix per name and three shared materials; inner
// shells dropped before reduction and the per-piece volume guard of the decimater (baobab,
// bush, fir, honda, ...).
// Changed on purpose by issue 17 (species that read): leaves fill a one-leaf shell under a
// meshed crown instead of its whole volume (every template with a crown and leaves), the
// reworked oak, spruce, willow, palm and baobab, and seed 001's spruce kept as seed_spruce.
// Changed on purpose by the reducer's passes (issue 11): the bulk of the collapses in
// sorted passes instead of one heap (DecimateSettings::fast_passes), another order of
// collapses with the same tests (every template); trunk and crown kept at a quarter of the
// budget each within the one reduction (DecimateSettings::part_floor) instead of a second
// reduction of a starved part (spruce).
// Changed on purpose by drop_hidden's twigs (issue 11): twigs thinner than half a cell whose
// axis lies inside the crown are left out of a game mesh's trunk, which is meshed at the
// budget's resolution (spruce), and the willow, fir, elm and maple use drop_hidden now.
// Changed on purpose by the snapshot's rule (issue 11): the direct reduction keeps the parts
// at the handle-cutting count only where the handles' floor is at least half the budget,
// so elsewhere the passes run down to 4096 triangles instead of 6400 (the heap's share at
// 800): another order for some collapses (every template whose floor is small: not the
// bush, fir, maple, spruce and ternary).
// Changed on purpose by handle cutting's loops (issue 11): a round offers every loop of a
// cell instead of the shortest, so fewer rounds cut the same handles (bush, fir, spruce,
// ternary: other handles cut).
// Changed on purpose by drop_hidden in four more templates (issue 11): the oak's, cypress's,
// windswept's and ternary's game meshes leave out the branches their crowns hide.
// Changed on purpose by the crown's cells for a budget (issue 11): 2 sqrt(budget / 2) instead
// of 2.4 (40 cells at 800 instead of 48; every crown above 40 cells).
// Changed on purpose by the baobab's trunk_resolution (issue 11): 85 cells instead of 100,
// the same mean error at 800 within 2.4% from a quarter fewer raw trunk triangles.
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
        {"oak.obj", 0xdc162eaec14b375ull},
        {"oak.glb", 0xe51c91345e679c01ull},
        {"oak.ply", 0x863d896b0990ce40ull},
        {"baobab.obj", 0xbf134de6e9abd8e7ull},
        {"baobab.glb", 0x17e89526eea972bbull},
        {"baobab.ply", 0xed4f35d5656af8d1ull},
        {"birch.obj", 0x55823572d9fdff4full},
        {"birch.glb", 0xc586de917924cb29ull},
        {"birch.ply", 0x2ec9a336dd2a414full},
        {"bush.obj", 0xb006c887e031f9fbull},
        {"bush.glb", 0x3698dd7a68a3c05full},
        {"bush.ply", 0x6ca9cea1f79f96eeull},
        {"cypress.obj", 0xf4d33739941eeb58ull},
        {"cypress.glb", 0x61f1dc934b95efe3ull},
        {"cypress.ply", 0x27ae0c46e7553379ull},
        {"fir.obj", 0xc4e522bf58134d30ull},
        {"fir.glb", 0x46b9f9e1384b627aull},
        {"fir.ply", 0x34bbd717f8109b0cull},
        {"honda.obj", 0xf455d7194c397b33ull},
        {"honda.glb", 0x8fd25aeaf24ef508ull},
        {"honda.ply", 0x3b5e82dcea3374f4ull},
        {"palm.obj", 0xab8097f16f190e30ull},
        {"palm.glb", 0xf1b14d621b3c4056ull},
        {"palm.ply", 0xce2d11bedd8aa616ull},
        {"pine.obj", 0x502428bff12344cfull},
        {"pine.glb", 0xafdb8c7acff248deull},
        {"pine.ply", 0xa70da0aba2ad365aull},
        {"spruce.obj", 0x987878a194486194ull},
        {"spruce.glb", 0x800630ebfc58e185ull},
        {"spruce.ply", 0x221b46a43281e32cull},
        {"seed_spruce.obj", 0x1d9819b755a87470ull},
        {"seed_spruce.glb", 0x3daeb338e16dd534ull},
        {"seed_spruce.ply", 0xc5a2bb9ee823431eull},
        {"ternary.obj", 0xdbd21132abd2f175ull},
        {"ternary.glb", 0x3fa06f1e66d2869bull},
        {"ternary.ply", 0x210f855bd6f605c0ull},
        {"willow.obj", 0xdf555ccd7d277388ull},
        {"willow.glb", 0xbd7fb9768a81f62full},
        {"willow.ply", 0x98efbf75c1ce1fbdull},
        {"elm.obj", 0xe52498ca24cf8434ull},
        {"elm.glb", 0xed47f45019916b58ull},
        {"elm.ply", 0x4f32a66a2b6af87dull},
        {"maple.obj", 0xbfafe513db269e8cull},
        {"maple.glb", 0x763b9a9f8d96c6e6ull},
        {"maple.ply", 0x1b83fb6081f41d44ull},
        {"hedge.obj", 0x59cff3ba36c68fe7ull},
        {"hedge.glb", 0xef2a58f38de87ea2ull},
        {"hedge.ply", 0xd23a7a5b5642baf5ull},
        {"windswept.obj", 0xe76b8d9b3704a6c4ull},
        {"windswept.glb", 0x6f2f9cb376aa212cull},
        {"windswept.ply", 0x7dc2f1efcabc3983ull},
        // `export -t palm --lod -o palm_lod.glb` and `... -o palm_lod.obj` (MTL, LOD0-LOD3).
        {"palm_lod.glb", 0x346addd0f92b6299ull},
        {"palm_lod.obj", 0x62878570a848867ull},
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
