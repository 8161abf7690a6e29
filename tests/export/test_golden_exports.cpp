// Every built-in template exported as `sylva export -t NAME -o NAME.{obj,glb,ply}` does,
// hashed byte for byte against the files the release before the re-cut (issue 10) wrote.
// A change here must be on purpose: update the hash and say why in the commit.
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
        {"oak.obj", 0x91436baf53ec4f96ull},
        {"oak.glb", 0x3db96e87e53e82a4ull},
        {"oak.ply", 0x023a5def66b37c49ull},
        {"baobab.obj", 0x6acf39f9034684a0ull},
        {"baobab.glb", 0xaadd5fa66258b3d2ull},
        {"baobab.ply", 0x28347fb2330bcf51ull},
        {"birch.obj", 0x796dd1754b951a2dull},
        {"birch.glb", 0x061a01f75efd28ffull},
        {"birch.ply", 0x4c53c86f9ccb99d3ull},
        {"bush.obj", 0x5951d0ac0bf78001ull},
        {"bush.glb", 0x8a307783d01419cdull},
        {"bush.ply", 0x27be3305bc9e3d2dull},
        {"cypress.obj", 0x6e17bbdef72d18ccull},
        {"cypress.glb", 0xc78feb7f8f0fc294ull},
        {"cypress.ply", 0x8be5149fa98c0bbcull},
        {"fir.obj", 0x263e363d31fcbfdcull},
        {"fir.glb", 0x3f862639f8db228cull},
        {"fir.ply", 0x6be8ee9598c021d1ull},
        {"honda.obj", 0x7301c8f7903d5b52ull},
        {"honda.glb", 0xe0aa3fbd2a293388ull},
        {"honda.ply", 0x7ca45d91b177b0b8ull},
        {"palm.obj", 0xbee7f1474330d35full},
        {"palm.glb", 0x933ae7ba3544cd29ull},
        {"palm.ply", 0x1afa55af9b0523c2ull},
        {"pine.obj", 0x6bec8b6183737bccull},
        {"pine.glb", 0x852a2e84f1e63044ull},
        {"pine.ply", 0x105b4b74d34fbad0ull},
        {"spruce.obj", 0xd848f7ccf62a1d47ull},
        {"spruce.glb", 0x0acb9df5e45abd4dull},
        {"spruce.ply", 0xfa6a601855302b90ull},
        {"ternary.obj", 0xfddda440950baba0ull},
        {"ternary.glb", 0x3a33738124de20bbull},
        {"ternary.ply", 0x10035aa4a4bad40full},
        {"willow.obj", 0x5700784f797342bdull},
        {"willow.glb", 0xfbbfe898759c18f9ull},
        {"willow.ply", 0x6b2e34f8c0e9201aull},
        // `export -t palm --lod -o palm_lod.glb` and `... -o palm_lod.obj` (MTL, LOD0-LOD3).
        {"palm_lod.glb", 0x7b54a60d188a8dc1ull},
        {"palm_lod.obj", 0x5ae0c7e46756f334ull},
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
        const Tree tree = generate_tree(tmpl);
        FinishSettings finish;
        finish.budget.total = static_cast<std::size_t>(tmpl.params.triangle_budget);
        finish.lod = lod;
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
            EXPECT_EQ(fnv1a(files), expected->second)
                << key << " is no longer byte-identical to the export before the re-cut";
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
