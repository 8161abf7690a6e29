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
// Changed on purpose by the crown's fold nearest sphere first (issue 11): the spheres within
// 4 k of the nearest folded by distance instead of in the order of the tips, four distances
// at a time (every template with a crown but the seed's spruce: where three or more spheres
// blend, the surface moves by up to a fifth of the blend width, a centimetre on the fir; the
// leaves in its shell with it).
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
        {"oak.obj", 0x4ba9844536310589ull},
        {"oak.glb", 0x5968706a3971df44ull},
        {"oak.ply", 0xb1d7619585cf688aull},
        {"baobab.obj", 0x18374c88b249d61full},
        {"baobab.glb", 0xbc86ba0da2316d8cull},
        {"baobab.ply", 0x5c71f49aac440f7aull},
        {"birch.obj", 0x7ab96e0696fc5823ull},
        {"birch.glb", 0xb93bcabc6f528cd9ull},
        {"birch.ply", 0x24502aaa760d5324ull},
        {"bush.obj", 0xb006c887e031f9fbull},
        {"bush.glb", 0x3698dd7a68a3c05full},
        {"bush.ply", 0x6ca9cea1f79f96eeull},
        {"cypress.obj", 0x9aa64169b9f1112full},
        {"cypress.glb", 0x2aa3cfc68e044df6ull},
        {"cypress.ply", 0x413419ab7fe70107ull},
        {"fir.obj", 0x8005c330982f285ull},
        {"fir.glb", 0xc862ce37f42e2dadull},
        {"fir.ply", 0xe8a5d9fdc1d4012ull},
        {"honda.obj", 0x24f0966ee428aa8cull},
        {"honda.glb", 0xc3c8a4d248dac7dcull},
        {"honda.ply", 0x57a4bcb255a4ca7ull},
        {"palm.obj", 0xab8097f16f190e30ull},
        {"palm.glb", 0xf1b14d621b3c4056ull},
        {"palm.ply", 0xce2d11bedd8aa616ull},
        {"pine.obj", 0x6b84ee1ef01c9164ull},
        {"pine.glb", 0xf4882929e825e89ull},
        {"pine.ply", 0x40e48acccef3e30full},
        {"spruce.obj", 0x6d4e323c5e6a85a0ull},
        {"spruce.glb", 0xd706add45f7592b7ull},
        {"spruce.ply", 0x8b95bbad7cb8d3ceull},
        {"seed_spruce.obj", 0x1d9819b755a87470ull},
        {"seed_spruce.glb", 0x3daeb338e16dd534ull},
        {"seed_spruce.ply", 0xc5a2bb9ee823431eull},
        {"ternary.obj", 0x8de8b59cafc38552ull},
        {"ternary.glb", 0x1237740bba75ac92ull},
        {"ternary.ply", 0x63c6447a8b9701faull},
        {"willow.obj", 0xd4da224deb6cc713ull},
        {"willow.glb", 0x9f9219cfc0497ffdull},
        {"willow.ply", 0xcf18dbb7da04469full},
        {"elm.obj", 0xa766ac9e8569dc80ull},
        {"elm.glb", 0xdcddb0059936f74aull},
        {"elm.ply", 0xf9399c77d57c4eb4ull},
        {"maple.obj", 0x98c04e4935d32762ull},
        {"maple.glb", 0x5927e49b1f1cdc48ull},
        {"maple.ply", 0xf11be5277be6a081ull},
        {"hedge.obj", 0x53fca155d2054821ull},
        {"hedge.glb", 0x3b4cc56ddca5f3fdull},
        {"hedge.ply", 0x36342e90119751a0ull},
        {"windswept.obj", 0x95fa2c85829e0b8eull},
        {"windswept.glb", 0x2be4f2f6dedf73f0ull},
        {"windswept.ply", 0xc4ac119b289eb54eull},
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
