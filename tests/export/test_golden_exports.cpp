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
        {"oak.obj", 0x6a29e4e07be209d1ull},
        {"oak.glb", 0x6b008792b65721c5ull},
        {"oak.ply", 0xe4f7a964749dc6a8ull},
        {"baobab.obj", 0x9ecf94a0bad13292ull},
        {"baobab.glb", 0xa82cf7a15de192bfull},
        {"baobab.ply", 0xa15cdaea42d345f1ull},
        {"birch.obj", 0xb9cb9dac6102f097ull},
        {"birch.glb", 0x2c8064fbbdd4930eull},
        {"birch.ply", 0xb759e76f5f43450dull},
        {"bush.obj", 0xf05a06880ab6b350ull},
        {"bush.glb", 0xb70d597aabf41cb9ull},
        {"bush.ply", 0xfd5cd530f0771eb3ull},
        {"cypress.obj", 0x77661790c7b07de2ull},
        {"cypress.glb", 0x27904d2a86381477ull},
        {"cypress.ply", 0x64fd83280a09a0eeull},
        {"fir.obj", 0xd4bcd00e19c4591eull},
        {"fir.glb", 0xe1c6ec1b4b689954ull},
        {"fir.ply", 0x205d9ccec7e36e34ull},
        {"honda.obj", 0xeb891025d9cb9531ull},
        {"honda.glb", 0x2e48d5810bd2167dull},
        {"honda.ply", 0xb900c72839cfd027ull},
        {"palm.obj", 0x54b183d4ab5f8edaull},
        {"palm.glb", 0x2833c31fde5ab3c7ull},
        {"palm.ply", 0x15a69bbcad8a8b5ull},
        {"pine.obj", 0xa8344609d682c5e6ull},
        {"pine.glb", 0x81eebe77fbc4d4a5ull},
        {"pine.ply", 0x7dfb7eb9cd1bc3bbull},
        {"spruce.obj", 0x8edcb9142cefc22eull},
        {"spruce.glb", 0xf62669a028c2590bull},
        {"spruce.ply", 0xd356cb43773d852aull},
        {"seed_spruce.obj", 0x79d835182a54673eull},
        {"seed_spruce.glb", 0x820f28a207e8cb63ull},
        {"seed_spruce.ply", 0x2cf1b086ca3199feull},
        {"ternary.obj", 0x19ff30110bfaf559ull},
        {"ternary.glb", 0x4541b307f9d12674ull},
        {"ternary.ply", 0x3031724864a323efull},
        {"willow.obj", 0x392398381e76ac0full},
        {"willow.glb", 0x7797bfae1b9613e1ull},
        {"willow.ply", 0x74a1e8b5ee10b774ull},
        {"elm.obj", 0x8ab4e1d5fceeff17ull},
        {"elm.glb", 0x6322ac5af803cc61ull},
        {"elm.ply", 0x92ec5198569268e2ull},
        {"maple.obj", 0x88e154089d55b6b5ull},
        {"maple.glb", 0x9e2e5323d7fde68aull},
        {"maple.ply", 0x6f7e0832c79cd556ull},
        {"hedge.obj", 0x1c78adad3f5f971eull},
        {"hedge.glb", 0x41a42794fab1a4a7ull},
        {"hedge.ply", 0x506821b776aeb1c1ull},
        {"windswept.obj", 0x5fd2cfaeffeed49ull},
        {"windswept.glb", 0x2dbe4f3950a2adf0ull},
        {"windswept.ply", 0x4317d212896ef4d5ull},
        // `export -t palm --lod -o palm_lod.glb` and `... -o palm_lod.obj` (MTL, LOD0-LOD3).
        {"palm_lod.glb", 0x268dd0b978d62975ull},
        {"palm_lod.obj", 0x4650f2a1b2fec0b8ull},
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
