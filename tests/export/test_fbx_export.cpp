// FBX export: the container round-trips and refuses bad bytes with InputError; a tree's
// FBX (read back with our decoder) holds a LOD group with one mesh per level, every UV and
// colour set, the tree's own material names, metres and Y up; the unreal profile's hulls
// are named for the finest level's mesh; and assimp's FBX reader (an independent one)
// reads the file with the same meshes and nodes. scripts/engine-check imports it in Blender.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "core/errors.h"
#include "export/export_tree.h"
#include "export/fbx_document.h"
#include "export/fbx_writer.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

TEST(FbxDocument, RoundTripsEveryValueTypeItWrites) {
    std::vector<fbx::Node> top(2);
    top[0].name = "A";
    top[0].values = {fbx::int32(-7),
                     fbx::int64(1LL << 40),
                     fbx::float64(0.1),
                     fbx::character('T'),
                     fbx::string(std::string("a\0b", 3)),
                     fbx::raw("xyz"),
                     fbx::int32_array({1, -2, 3}),
                     fbx::float64_array({1.5, -2.25})};
    top[0].add("Empty");
    top[0].add("Child", {fbx::int32(1)}).add("Grandchild", {fbx::string("g")});
    top[1].name = "B";
    for (std::uint32_t version : {7400u, 7500u}) {
        const fbx::Document doc = fbx::decode_fbx(fbx::encode_fbx(top, version));
        EXPECT_EQ(doc.version, version);
        ASSERT_EQ(doc.top.size(), 2u);
        const fbx::Node& a = doc.top[0];
        ASSERT_EQ(a.values.size(), 8u);
        EXPECT_EQ(a.values[0].integer, -7);
        EXPECT_EQ(a.values[1].integer, 1LL << 40);
        EXPECT_EQ(a.values[2].real, 0.1);
        EXPECT_EQ(a.values[3].integer, 'T');
        EXPECT_EQ(a.values[4].text, std::string("a\0b", 3));
        EXPECT_EQ(a.values[5].code, 'R');
        EXPECT_EQ(a.values[6].integers, (std::vector<std::int64_t>{1, -2, 3}));
        EXPECT_EQ(a.values[7].reals, (std::vector<double>{1.5, -2.25}));
        ASSERT_EQ(a.children.size(), 2u);
        EXPECT_EQ(a.children[1].children.at(0).values.at(0).text, "g");
        EXPECT_EQ(doc.top[1].name, "B");
    }
}

TEST(FbxDocument, RefusesBadBytesWithInputError) {
    const std::string good = fbx::encode_fbx({fbx::Node{"A", {fbx::int32(1)}, {}}});
    EXPECT_THROW(fbx::decode_fbx("not an fbx file at all, really"), InputError);
    EXPECT_THROW(fbx::decode_fbx(good.substr(0, 30)), InputError) << "cut in a record";
    std::string bad_offset = good;
    bad_offset[27] = '\x7f';  // the first record's end offset, far past the file
    EXPECT_THROW(fbx::decode_fbx(bad_offset), InputError);
    std::string bad_type = good;
    bad_type[27 + 13 + 1] = 'Z';  // the first value's type letter
    EXPECT_THROW(fbx::decode_fbx(bad_type), InputError);
}

// The objects of a decoded file by id, and the OO connections child -> parent.
struct Scene {
    std::map<std::int64_t, const fbx::Node*> objects;
    std::multimap<std::int64_t, std::int64_t> parent_of;
    fbx::Document doc;

    const fbx::Node& top(std::string_view name) const {
        for (const fbx::Node& n : doc.top)
            if (n.name == name) return n;
        throw std::out_of_range(std::string(name));
    }
    // Objects of `type` ("Model") whose name (before \x00\x01) is `name`.
    const fbx::Node* named(std::string_view type, const std::string& name) const {
        for (const auto& [id, n] : objects)
            if (n->name == type &&
                n->values.at(1).text.substr(0, n->values[1].text.find('\0')) == name)
                return n;
        return nullptr;
    }
    std::vector<const fbx::Node*> children(std::int64_t parent, std::string_view type) const {
        std::vector<const fbx::Node*> out;
        for (const auto& [child, p] : parent_of)
            if (p == parent && objects.count(child) && objects.at(child)->name == type)
                out.push_back(objects.at(child));
        return out;
    }
};

Scene read_scene(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    Scene s;
    s.doc = fbx::decode_fbx(bytes, path.string());
    for (const fbx::Node& n : s.top("Objects").children) s.objects[n.values.at(0).integer] = &n;
    for (const fbx::Node& c : s.top("Connections").children)
        s.parent_of.emplace(c.values.at(1).integer, c.values.at(2).integer);
    return s;
}

double property(const fbx::Node& owner, const std::string& name) {
    for (const fbx::Node& p : owner.find("Properties70")->children)
        if (p.values.at(0).text == name)
            return p.values.at(4).code == 'D' ? p.values[4].real : p.values[4].integer;
    throw std::out_of_range(name);
}

class FbxExport : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sylva_fbx_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path export_fbx(const std::string& name, EngineProfile profile, bool lod) {
        const TreeTemplate tmpl = load_template(name);
        FinishSettings finish;
        finish.budget.total = 400;
        finish.lod = lod;
        finish.lod_levels = 3;
        MeshOptions mesh;
        mesh.budget = game_budget(finish);
        const Tree tree = generate_tree(tmpl, mesh);
        ExportOptions options;
        options.profile = profile;
        options.material_prefix = material_prefix(tmpl.name, tmpl.params.seed);
        options.engine.wind_motion = wind_motion(tmpl.params);
        const fs::path path = dir_ / (name + ".fbx");
        write_tree(path, tree, finish_tree(tree, finish), tmpl.colors, options);
        return path;
    }

    fs::path dir_;
};

TEST_F(FbxExport, ALodChainIsALodGroupOfOneMeshPerLevelWithEverySet) {
    const Scene s = read_scene(export_fbx("oak", EngineProfile::Unity, true));
    EXPECT_EQ(s.doc.version, 7400u);
    const fbx::Node& settings = s.top("GlobalSettings");
    EXPECT_EQ(property(settings, "UpAxis"), 1) << "Y up";
    EXPECT_EQ(property(settings, "UnitScaleFactor"), 100.0) << "metres";
    const fbx::Node* group = s.named("Model", "tree");
    ASSERT_NE(group, nullptr);
    EXPECT_EQ(group->values.at(2).text, "LodGroup");
    const auto attributes = s.children(group->values[0].integer, "NodeAttribute");
    ASSERT_EQ(attributes.size(), 1u);
    EXPECT_EQ(attributes[0]->values.at(2).text, "LodGroup");
    const auto levels = s.children(group->values[0].integer, "Model");
    ASSERT_EQ(levels.size(), 3u);
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const std::string name = levels[i]->values.at(1).text;
        EXPECT_EQ(name.substr(0, name.find('\0')), "tree_LOD" + std::to_string(i));
        EXPECT_EQ(levels[i]->values.at(2).text, "Mesh");
        const auto geometry = s.children(levels[i]->values[0].integer, "Geometry");
        ASSERT_EQ(geometry.size(), 1u);
        std::size_t uv_sets = 0, color_sets = 0;
        for (const fbx::Node& c : geometry[0]->children) {
            uv_sets += c.name == "LayerElementUV";
            color_sets += c.name == "LayerElementColor";
        }
        EXPECT_EQ(uv_sets, 3u) << "UVs, (sway, flex), (phase, flutter)";
        EXPECT_EQ(color_sets, 2u) << "tint, wind";
        // The wind to play it in, as user properties of the mesh and its materials (the
        // template's: the default wind).
        EXPECT_EQ(property(*levels[i], "sylva_wind_strength"), 0.3);
        EXPECT_EQ(property(*levels[i], "sylva_wind_gust_frequency"), 0.15);
        std::vector<std::string> materials;
        for (const fbx::Node* m : s.children(levels[i]->values[0].integer, "Material")) {
            const std::string full = m->values.at(1).text;
            materials.push_back(full.substr(0, full.find('\0')));
            EXPECT_EQ(property(*m, "sylva_wind_flutter"), 0.1) << materials.back();
            EXPECT_EQ(property(*m, "sylva_wind_direction_x"), 1.0) << materials.back();
        }
        EXPECT_EQ(materials,
                  (std::vector<std::string>{"oak_s1_trunk", "oak_s1_crown", "oak_s1_leaves"}));
    }
}

TEST_F(FbxExport, UnrealHullsAreNamedForTheFinestLevelsMesh) {
    const Scene s = read_scene(export_fbx("birch", EngineProfile::Unreal, true));
    ASSERT_NE(s.named("Model", "tree_LOD0"), nullptr);
    EXPECT_NE(s.named("Model", "UCX_tree_LOD0_00"), nullptr) << "the trunk hull";
    EXPECT_NE(s.named("Model", "UCX_tree_LOD0_01"), nullptr) << "a crown hull";
    const Scene one = read_scene(export_fbx("birch", EngineProfile::Unreal, false));
    ASSERT_NE(one.named("Model", "tree"), nullptr);
    EXPECT_EQ(one.named("Model", "tree")->values.at(2).text, "Mesh");
    EXPECT_NE(one.named("Model", "UCX_tree_00"), nullptr);
}

// assimp 5.2's FBX reader: exit 0, a mesh per level and part material (assimp splits a
// mesh by material), the level and hull nodes.
TEST_F(FbxExport, AssimpReadsTheFile) {
    const fs::path path = export_fbx("palm", EngineProfile::Unreal, true);
    FILE* pipe = ::popen(("assimp info '" + path.string() + "' --raw 2>&1").c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string output;
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    ASSERT_EQ(::pclose(pipe), 0) << "is assimp-utils installed? " << output;
    for (const char* node : {"tree_LOD0", "tree_LOD1", "tree_LOD2", "UCX_tree_LOD0_00"})
        EXPECT_NE(output.find(node), std::string::npos) << node << " in\n" << output;
    for (const char* material : {"palm_s1_trunk", "palm_s1_leaves"})
        EXPECT_NE(output.find(material), std::string::npos) << material << " in\n" << output;
}

}  // namespace
}  // namespace sylva
