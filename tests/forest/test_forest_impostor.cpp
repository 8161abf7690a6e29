// sylva forest with far levels: K variants bake K atlases, each tree of a variant draws its
// variant's images, no image is stored twice, and a forest without them has no images.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <map>
#include <set>
#include <string>

#include "forest/forest.h"
#include "forest/ground.h"
#include "tests/helpers.h"
#include "tree/template_library.h"

namespace {

namespace fs = std::filesystem;
using namespace sylva;
using namespace sylva::forest;

using ForestImpostor = test::TempFolderTest;

ForestSettings small_forest() {
    ForestSettings s;
    s.species = {{load_template("spruce"), 1.0}, {load_template("pine"), 1.0}};
    s.ground = rectangle_ground(40, 30);
    s.variants = 2;
    s.spacing = 4.0;
    s.stand_size = 15.0;
    s.seed = 3;
    s.trees = 16;
    s.finish.budget.total = 200;
    return s;
}

tinygltf::Model load(const fs::path& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF gltf;
    std::string error, warning;
    EXPECT_TRUE(gltf.LoadBinaryFromFile(&model, &error, &warning, path.string())) << error;
    return model;
}

// The bytes of an image stored in a buffer view (the PNG as written).
std::string image_bytes(const tinygltf::Model& model, const tinygltf::Image& image) {
    const tinygltf::BufferView& view =
        model.bufferViews.at(static_cast<std::size_t>(image.bufferView));
    const auto& data = model.buffers.at(static_cast<std::size_t>(view.buffer)).data;
    return {data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset),
            data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset + view.byteLength)};
}

TEST_F(ForestImpostor, EachVariantBakesOneAtlasThatAllItsTreesShare) {
    ForestSettings s = small_forest();
    s.export_options.impostor.kind = ImpostorKind::Octahedral;
    s.export_options.impostor.size = 128;
    s.export_options.impostor.views = 4;
    const ForestResult result = plant_forest(s, dir_ / "forest.glb");
    const std::size_t variants = result.plan.variants.size();
    ASSERT_EQ(variants, 4u);
    const tinygltf::Model model = load(dir_ / "forest.glb");

    // Two images (albedo, normal) per variant, every one distinct in name and bytes.
    ASSERT_EQ(model.images.size(), 2 * variants);
    std::set<std::string> names, bytes;
    for (const tinygltf::Image& image : model.images) {
        names.insert(image.name);
        const std::string png = image_bytes(model, image);
        EXPECT_EQ(png.substr(1, 3), "PNG") << image.name;
        bytes.insert(png);
    }
    EXPECT_EQ(names.size(), model.images.size());
    EXPECT_EQ(bytes.size(), model.images.size());

    // Every tree's impostor node draws the albedo of its own variant; the trees of a variant
    // share one mesh, and the layout in the node's extras names the same image.
    std::map<std::string, std::set<int>> meshes_of_variant;
    std::size_t trees = 0;
    for (int child : model.nodes[0].children) {
        const tinygltf::Node& tree = model.nodes[static_cast<std::size_t>(child)];
        const std::string variant = tree.extras.Get("sylva_variant").Get<std::string>();
        int impostor = -1;
        for (int c : tree.children)
            for (int part : model.nodes[static_cast<std::size_t>(c)].children)
                if (model.nodes[static_cast<std::size_t>(part)].name.ends_with("_impostor_LOD1"))
                    impostor = part;
        ASSERT_GE(impostor, 0) << tree.name;
        const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(impostor)];
        meshes_of_variant[variant].insert(node.mesh);
        const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(node.mesh)];
        const tinygltf::Material& material =
            model.materials[static_cast<std::size_t>(mesh.primitives.at(0).material)];
        const int texture = material.pbrMetallicRoughness.baseColorTexture.index;
        ASSERT_GE(texture, 0);
        const tinygltf::Image& image = model.images[static_cast<std::size_t>(
            model.textures[static_cast<std::size_t>(texture)].source)];
        EXPECT_EQ(image.name, variant + "_impostor_albedo");
        EXPECT_EQ(node.extras.Get("octahedral").Get("albedo").Get("image").Get<std::string>(),
                  image.name);
        ++trees;
    }
    EXPECT_EQ(trees, result.plan.placements.size());
    EXPECT_EQ(meshes_of_variant.size(), variants);
    for (const auto& [variant, meshes] : meshes_of_variant) EXPECT_EQ(meshes.size(), 1u) << variant;
}

TEST_F(ForestImpostor, AForestWithoutImpostorsStoresNoImage) {
    const ForestSettings s = small_forest();
    plant_forest(s, dir_ / "forest.glb");
    const tinygltf::Model model = load(dir_ / "forest.glb");
    EXPECT_TRUE(model.images.empty());
    EXPECT_TRUE(model.textures.empty());
}

}  // namespace
