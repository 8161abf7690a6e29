// Textured leaf cards (leaf_style = textured) as an export writes them, read back: a glb
// whose leaf material is alpha-tested and double-sided on an embedded texture of leaves
// drawn inside the cards' diamond, edges dilated; UVs on the cards within it; an OBJ with the
// texture beside its .mtl.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "export/export_tree.h"
#include "export/leaf_atlas.h"
#include "tests/helpers.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

class LeafAtlas : public test::TempFolderTest {
  protected:
    void export_oak(const std::string& name) {
        TreeTemplate t = load_template("oak");
        t.params.leaf_style = LeafStyle::Textured;
        FinishSettings finish;
        finish.budget.total = 800;
        MeshOptions mesh;
        mesh.budget = game_budget(finish);
        const Tree tree = generate_tree(t, mesh);
        write_tree(dir_ / name, tree, finish_tree(tree, finish), t.colors);
    }
};

TEST_F(LeafAtlas, AGlbDrawsTheCardsAlphaTestedOnAnEmbeddedTextureOfLeaves) {
    export_oak("oak.glb");
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, (dir_ / "oak.glb").string()))
        << error;
    const tinygltf::Material* leaves = nullptr;
    for (const tinygltf::Material& m : model.materials)
        if (m.name.ends_with("leaves")) leaves = &m;
    ASSERT_TRUE(leaves);
    EXPECT_EQ(leaves->alphaMode, "MASK");
    EXPECT_TRUE(leaves->doubleSided);
    const int texture = leaves->pbrMetallicRoughness.baseColorTexture.index;
    ASSERT_GE(texture, 0);
    const tinygltf::Image& image =
        model.images.at(static_cast<std::size_t>(model.textures.at(texture).source));
    EXPECT_EQ(image.name, "leaves_albedo");
    ASSERT_EQ(image.component, 4);
    const int n = image.width;
    ASSERT_EQ(image.height, n);
    // Leaves inside the diamond the cards' UVs cover (and only there), covering a fair part of
    // it; the transparent texels carry the leaves' colour, not black.
    std::size_t in_diamond = 0, covered = 0, outside = 0;
    double clear_green = 0.0, leaf_green = 0.0;
    std::size_t clear = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const unsigned char* px = &image.image[(static_cast<std::size_t>(y) * n + x) * 4];
            const float u = (x + 0.5f) / n, v = (y + 0.5f) / n;
            const bool inside = std::abs(u - 0.5f) + std::abs(v - 0.5f) <= 0.5f;
            in_diamond += inside;
            if (px[3] > 127) {
                ++covered;
                outside += !inside;
                leaf_green += px[1];
            } else {
                ++clear;
                clear_green += px[1];
            }
        }
    EXPECT_EQ(outside, 0u);
    EXPECT_GT(covered, in_diamond / 5);
    EXPECT_LT(covered, in_diamond * 4 / 5);
    EXPECT_GT(clear_green / clear, 0.6 * leaf_green / covered);
}

TEST_F(LeafAtlas, AnObjWritesTheTextureBesideItsMtl) {
    export_oak("oak.obj");
    ASSERT_TRUE(fs::exists(dir_ / "oak_leaves_albedo.png"));
    std::ifstream in(dir_ / "oak.mtl");
    const std::string mtl{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NE(mtl.find("map_Kd oak_leaves_albedo.png"), std::string::npos) << mtl;
    EXPECT_NE(mtl.find("map_d oak_leaves_albedo.png"), std::string::npos) << mtl;
}

TEST(LeafAtlasImage, IsTheSameForTheSameShapeAndDiffersByShape) {
    const glm::vec3 green(0.2f, 0.5f, 0.1f);
    EXPECT_EQ(leaf_atlas(LeafShape::Oak, green).albedo_png,
              leaf_atlas(LeafShape::Oak, green).albedo_png);
    EXPECT_NE(leaf_atlas(LeafShape::Oak, green).albedo_png,
              leaf_atlas(LeafShape::Needle, green).albedo_png);
}

}  // namespace
}  // namespace sylva
