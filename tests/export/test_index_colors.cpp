// Colour by index and the organs part, read back from the files (tinygltf for glb, the text
// of OBJ and PLY): the palette's colours in COLOR_0 and in OBJ/PLY vertex colours on white
// parts, an organs node with UVs, LOD levels that never gain organ triangles, and nothing of
// it for a template without a palette or organs (its COLOR_0 stays the white the generic
// profile writes beside the wind in COLOR_1).
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "export/export_tree.h"
#include "export/index_colors.h"
#include "tests/helpers.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

// A COLOR_0 accessor (normalized unsigned bytes, RGBA) as floats.
std::vector<glm::vec3> colors(const tinygltf::Model& model, int index) {
    const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(index));
    EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
    EXPECT_TRUE(a.normalized);
    const tinygltf::BufferView& v = model.bufferViews.at(static_cast<std::size_t>(a.bufferView));
    const unsigned char* data = model.buffers.at(static_cast<std::size_t>(v.buffer)).data.data() +
                                v.byteOffset + a.byteOffset;
    const std::size_t stride = v.byteStride ? v.byteStride : 4;
    std::vector<glm::vec3> out;
    for (std::size_t i = 0; i < a.count; ++i)
        out.push_back(glm::vec3(data[i * stride], data[i * stride + 1], data[i * stride + 2]) /
                      255.0f);
    return out;
}

bool near_palette(const glm::vec3& c, const std::vector<glm::vec3>& palette) {
    for (const glm::vec3& p : palette)
        if (glm::length(c - p) < 0.01f) return true;
    return false;
}

class IndexColors : public test::TempFolderTest {
  protected:
    // `name` exported at a small budget (and LOD levels) to `file`.
    std::vector<fs::path> write(const std::string& name, const std::string& file,
                                bool lod = false) {
        tmpl_ = load_template(name);
        tmpl_.params.trunk_resolution = 48;
        tmpl_.params.crown_resolution = 24;
        FinishSettings finish;
        finish.budget.total = 300;
        finish.lod = lod;
        finish.lod_levels = 3;
        MeshOptions mesh;
        mesh.budget = game_budget(finish);
        tree_ = generate_tree(tmpl_, mesh);
        finished_ = finish_tree(tree_, finish);
        return write_tree(dir_ / file, tree_, finished_, tmpl_.colors);
    }

    tinygltf::Model read_glb(const fs::path& path) {
        tinygltf::Model model;
        tinygltf::TinyGLTF loader;
        std::string error, warning;
        EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, path.string())) << error;
        return model;
    }

    TreeTemplate tmpl_;
    Tree tree_;
    FinishedTree finished_;
};

TEST_F(IndexColors, GlbCarriesThePaletteInColor0OnWhiteParts) {
    const tinygltf::Model model = read_glb(write("apple_tree", "apple.glb").front());
    const std::vector<glm::vec3>& palette = tmpl_.colors.palette;
    std::set<std::string> names;
    for (const tinygltf::Node& node : model.nodes) {
        if (node.mesh < 0) continue;
        names.insert(node.name);
        const tinygltf::Primitive& p =
            model.meshes[static_cast<std::size_t>(node.mesh)].primitives.at(0);
        const auto& factor = model.materials[static_cast<std::size_t>(p.material)]
                                 .pbrMetallicRoughness.baseColorFactor;
        if (node.name == "crown" || node.name == "leaves") {
            // Not drawn by index: the generic profile's COLOR_0 is white (its wind is in
            // COLOR_1), the part's colour its own.
            for (const glm::vec3& c : colors(model, p.attributes.at("COLOR_0")))
                EXPECT_EQ(c, glm::vec3(1.0f)) << node.name;
            EXPECT_NE(factor, (std::vector<double>{1, 1, 1, 1})) << node.name;
            continue;
        }
        ASSERT_EQ(p.attributes.count("COLOR_0"), 1u) << node.name;
        EXPECT_EQ(factor, (std::vector<double>{1, 1, 1, 1})) << node.name;
        std::set<int> seen;
        for (const glm::vec3& c : colors(model, p.attributes.at("COLOR_0"))) {
            EXPECT_TRUE(near_palette(c, palette)) << node.name;
            seen.insert(glm::length(c - palette[1]) < 0.01f ? 1 : 0);
        }
        // Wood is index 0, the apples index 1.
        EXPECT_EQ(seen, std::set<int>{node.name == "organs" ? 1 : 0}) << node.name;
        if (node.name == "organs") {
            EXPECT_EQ(p.attributes.count("TEXCOORD_0"), 1u);
            EXPECT_TRUE(model.materials[static_cast<std::size_t>(p.material)].doubleSided);
        }
    }
    EXPECT_EQ(names, (std::set<std::string>{"trunk", "crown", "leaves", "organs"}));
}

TEST_F(IndexColors, ObjAndPlyVertexColoursAndLodLevels) {
    const std::vector<fs::path> obj = write("flowering_shrub", "shrub.obj");
    std::ifstream in(obj.front());
    std::string line;
    std::size_t coloured = 0, petals = 0;
    const glm::vec3 petal = tmpl_.colors.palette[2];
    while (std::getline(in, line)) {
        if (line.rfind("v ", 0) != 0) continue;
        std::istringstream v(line.substr(2));
        glm::vec3 p, c;
        ASSERT_TRUE(v >> p.x >> p.y >> p.z >> c.r >> c.g >> c.b) << line;
        ++coloured;
        EXPECT_TRUE(near_palette(c, tmpl_.colors.palette)) << line;
        petals += glm::length(c - petal) < 0.01f;
    }
    EXPECT_GT(coloured, 100u);
    EXPECT_GT(petals, 20u);
    const std::vector<fs::path> ply = write("flowering_shrub", "shrub.ply");
    std::ifstream header(ply.front(), std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(header)), {});
    EXPECT_NE(text.find("property uchar red"), std::string::npos);

    // A LOD chain: every level has its organs, never more triangles than the level before.
    write("flowering_shrub", "shrub_lod.glb", true);
    ASSERT_EQ(finished_.organs.size(), 3u);
    for (std::size_t i = 1; i < finished_.organs.size(); ++i)
        EXPECT_LE(finished_.organs[i].mesh.triangles.size(),
                  finished_.organs[i - 1].mesh.triangles.size());
    EXPECT_LE(finished_.organs[0].mesh.triangles.size(), finished_.leaf_budgets[0]);
}

TEST_F(IndexColors, NoPaletteNoOrgansNothingChanges) {
    const tinygltf::Model model = read_glb(write("birch", "birch.glb").front());
    for (const tinygltf::Node& node : model.nodes) {
        if (node.mesh < 0) continue;
        EXPECT_NE(node.name, "organs");
        const tinygltf::Primitive& p =
            model.meshes[static_cast<std::size_t>(node.mesh)].primitives.at(0);
        for (const glm::vec3& c : colors(model, p.attributes.at("COLOR_0")))
            EXPECT_EQ(c, glm::vec3(1.0f)) << node.name;
    }
    EXPECT_TRUE(finished_.organs.empty());
}

TEST(PaletteColor, IndicesWrapAround) {
    const std::vector<glm::vec3> palette{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    EXPECT_EQ(palette_color(palette, 0), palette[0]);
    EXPECT_EQ(palette_color(palette, 4), palette[1]);
    EXPECT_EQ(palette_color(palette, -1), palette[2]);
    EXPECT_EQ(palette_color({}, 3), glm::vec3(1.0f));
}

}  // namespace
}  // namespace sylva
