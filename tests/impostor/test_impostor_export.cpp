// The far levels as an export writes them (export/impostor_level.h), read back: a glb with
// the impostor and billboard levels (alpha-tested materials on embedded PNGs, tangents, the
// layout in the node's extras), an OBJ chain with its PNGs and .mtl beside it, the sidecar
// JSON, the same bytes twice, and the CLI's flags.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/color_variation.h"
#include "export/export_tree.h"
#include "impostor/atlas_sampler.h"
#include "tests/helpers.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

using test::read_file;

class ImpostorExport : public test::TempFolderTest {
  protected:
    // The default template's game tree exported to `name` with `kind`.
    std::vector<fs::path> export_tree(const std::string& name, ImpostorKind kind, bool lod) {
        TreeTemplate t = load_template("default");
        t.colors = tree_colors(t);
        FinishSettings finish;
        finish.budget.total = static_cast<std::size_t>(t.params.triangle_budget);
        finish.lod = lod;
        MeshOptions mesh;
        mesh.budget = game_budget(finish);
        const Tree tree = generate_tree(t, mesh);
        const FinishedTree finished = finish_tree(tree, finish);
        ExportOptions options;
        options.impostor.kind = kind;
        options.impostor.size = 256;  // small: the layout, not the look, is tested here
        return write_tree(dir_ / name, tree, finished, t.colors, options);
    }
};

TEST_F(ImpostorExport, AGlbCarriesBothFarLevelsWithEmbeddedTextures) {
    export_tree("tree.glb", ImpostorKind::Both, false);
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, (dir_ / "tree.glb").string()))
        << error;
    // LOD0 the tree, LOD1 the billboard, LOD2 the impostor.
    std::vector<std::string> names;
    for (const tinygltf::Node& node : model.nodes) names.push_back(node.name);
    for (const char* expected : {"tree_LOD0", "billboard_LOD1", "impostor_LOD2"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
    ASSERT_EQ(model.images.size(), 4u);  // albedo and normal of each
    for (const tinygltf::Image& image : model.images) {
        EXPECT_EQ(image.mimeType, "image/png");
        EXPECT_GE(image.bufferView, 0);  // embedded
    }
    int textured = 0;
    for (const tinygltf::Material& m : model.materials) {
        if (m.name != "impostor" && m.name != "billboard") continue;
        ++textured;
        EXPECT_EQ(m.alphaMode, "MASK");
        EXPECT_DOUBLE_EQ(m.alphaCutoff, 0.5);
        EXPECT_TRUE(m.doubleSided);
        EXPECT_GE(m.pbrMetallicRoughness.baseColorTexture.index, 0);
        EXPECT_GE(m.normalTexture.index, 0);
    }
    EXPECT_EQ(textured, 2);
    for (const tinygltf::Sampler& s : model.samplers) {
        if (s.minFilter == TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR) {
            EXPECT_EQ(s.wrapS, TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
        }
    }
    for (const tinygltf::Node& node : model.nodes) {
        if (node.name != "impostor_LOD2") continue;
        const tinygltf::Mesh& mesh = model.meshes.at(static_cast<std::size_t>(node.mesh));
        const auto& attributes = mesh.primitives.at(0).attributes;
        EXPECT_TRUE(attributes.count("TEXCOORD_0") && attributes.count("TANGENT"));
        ASSERT_TRUE(node.extras.Has("octahedral"));
        const tinygltf::Value& o = node.extras.Get("octahedral");
        EXPECT_EQ(o.Get("views").GetNumberAsInt(), 8);
        EXPECT_EQ(o.Get("tile").GetNumberAsInt(), 32);
        EXPECT_GT(o.Get("radius").GetNumberAsDouble(), 1.0);
        EXPECT_EQ(o.Get("albedo").Get("image").Get<std::string>(), "impostor_albedo");
    }
    // The sidecar names the glb's images.
    const nlohmann::json layout = nlohmann::json::parse(read_file(dir_ / "tree_impostor.json"));
    EXPECT_EQ(layout["format"], "sylva-impostor");
    EXPECT_EQ(layout["octahedral"]["normal"]["image"], "impostor_normal");
    // The numbers the shaders' march through each view's depth uses.
    EXPECT_EQ(layout["octahedral"]["relief_steps"], kImpostorReliefSteps);
    EXPECT_EQ(layout["octahedral"]["relief_refinements"], kImpostorReliefRefinements);
    EXPECT_EQ(layout["octahedral"]["surface_texels"], kImpostorSurfaceTexels);
    EXPECT_EQ(layout["billboard"]["quads"], 3);
}

TEST_F(ImpostorExport, AnObjChainWritesThePngsBesideIt) {
    const std::vector<fs::path> files = export_tree("tree.obj", ImpostorKind::Both, true);
    // LOD0-LOD3 of the tree, LOD4 the billboard, LOD5 the impostor.
    for (const char* name :
         {"tree_LOD3.obj", "tree_LOD4.obj", "tree_LOD5.obj", "tree.mtl", "tree_impostor_albedo.png",
          "tree_impostor_normal.png", "tree_billboard_albedo.png", "tree_billboard_normal.png",
          "tree_impostor.json"})
        EXPECT_TRUE(fs::exists(dir_ / name)) << name;
    EXPECT_FALSE(fs::exists(dir_ / "tree_LOD6.obj"));
    const std::string mtl = read_file(dir_ / "tree.mtl");
    EXPECT_NE(mtl.find("newmtl impostor\n"), std::string::npos) << mtl;
    EXPECT_NE(mtl.find("map_Kd tree_impostor_albedo.png"), std::string::npos) << mtl;
    EXPECT_NE(mtl.find("map_d tree_billboard_albedo.png"), std::string::npos) << mtl;
    EXPECT_NE(mtl.find("norm tree_impostor_normal.png"), std::string::npos) << mtl;
    const std::string lod5 = read_file(dir_ / "tree_LOD5.obj");
    EXPECT_NE(lod5.find("usemtl impostor"), std::string::npos);
    EXPECT_NE(lod5.find("vt "), std::string::npos);
    const nlohmann::json layout = nlohmann::json::parse(read_file(dir_ / "tree_impostor.json"));
    EXPECT_EQ(layout["octahedral"]["albedo"]["image"], "tree_impostor_albedo.png");
    // A PNG is a PNG.
    EXPECT_EQ(read_file(dir_ / "tree_impostor_albedo.png").substr(1, 3), "PNG");
}

TEST_F(ImpostorExport, TheSameTreeExportsTheSameBytes) {
    export_tree("a.glb", ImpostorKind::Octahedral, true);
    export_tree("b.glb", ImpostorKind::Octahedral, true);
    EXPECT_EQ(read_file(dir_ / "a.glb"), read_file(dir_ / "b.glb"));
}

test::CommandResult sylva(const std::string& args) {
    return test::run_command(std::string(SYLVA_BINARY_DIR) + "/app/sylva " + args);
}

TEST_F(ImpostorExport, TheCliRefusesPlyAndBadValues) {
    const std::string out = " -o " + (dir_ / "t").string();
    EXPECT_EQ(sylva("export --impostor" + out + ".ply").code, 2);
    EXPECT_EQ(sylva("export --impostor-kind round" + out + ".glb").code, 2);
    EXPECT_EQ(sylva("export --impostor-views 1" + out + ".glb").code, 2);
    EXPECT_EQ(sylva("export --impostor-quads 5" + out + ".glb").code, 2);
    const test::CommandResult ok =
        sylva("export --impostor --impostor-size 128 --impostor-views 4" + out + ".glb");
    EXPECT_EQ(ok.code, 0) << ok.output;
    EXPECT_NE(ok.output.find("LOD1: octahedral impostor, 4 x 4 views of 32 px"), std::string::npos)
        << ok.output;
    EXPECT_TRUE(fs::exists(dir_ / "t_impostor.json"));
}

TEST_F(ImpostorExport, TheCliSaysWhichLayoutItChose) {
    const test::CommandResult ok = sylva("export --impostor -o " + (dir_ / "t.glb").string());
    ASSERT_EQ(ok.code, 0) << ok.output;
    const nlohmann::json layout = nlohmann::json::parse(read_file(dir_ / "t_impostor.json"));
    const std::string choice = layout["octahedral"]["layout_choice"];
    ASSERT_EQ(choice.rfind("auto: ", 0), 0u) << choice;
    // The one layout baked, as the JSON says it, not the two it could have been.
    EXPECT_NE(ok.output.find("LOD1: octahedral impostor, " + choice + "\n"), std::string::npos)
        << ok.output;
}

}  // namespace
}  // namespace sylva
