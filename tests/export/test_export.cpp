// The exporters as other programs see them: the .glb opens in a real glTF consumer
// (Debian's assimp, run as `assimp info`), the OBJ and its MTL read back through an
// independent minimal parser (and assimp), the PLY header and body match, the format
// follows the extension, LOD chains carry the _LOD suffixes, and failed writes leave
// nothing behind.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "core/errors.h"
#include "core/mesh_checks.h"
#include "export/export.h"
#include "export/export_tree.h"
#include "export/glb_writer.h"
#include "export/mesh_normals.h"
#include "export/obj_writer.h"
#include "export/ply_writer.h"
#include "marching/marching_cubes.h"
#include "tests/helpers.h"
#include "tree/leaf_thinning.h"
#include "tree/lowpoly_tree.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
    fs::path dir = fs::temp_directory_path() / ("sylva_export_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// The default tree, meshed coarsely (fast) and reduced to a game budget, with its leaves.
struct SmallTree {
    Tree tree;
    ReducedTree reduced;
    PartColors colors;
    std::vector<NamedMesh> parts() const {
        return tree_parts(reduced.trunk, reduced.crown, reduced.leaves, colors);
    }
};

const SmallTree& small_tree() {
    static const SmallTree t = [] {
        SmallTree s;
        TreeTemplate tmpl = default_template();
        tmpl.params.trunk_resolution = 40;
        tmpl.params.crown_resolution = 32;
        s.tree = generate_tree(tmpl);
        s.reduced = reduce_tree(s.tree, TreeBudget{});
        s.colors = tmpl.colors;
        return s;
    }();
    return t;
}

using test::read_file;

// What `assimp info --raw` (no post-processing: no vertex welding, no instancing)
// reports: meshes (name, vertices, faces), material names, nodes with the mesh they hold.
struct AssimpInfo {
    struct MeshInfo {
        std::string name;
        std::size_t vertices = 0, faces = 0;
    };
    std::vector<MeshInfo> meshes;
    std::vector<std::string> materials;  // named ones (raw imports add an unnamed default)
    std::vector<std::pair<std::string, int>> nodes;  // name, mesh index or -1
    std::string raw;

    const MeshInfo& mesh_of(const std::string& node) const {
        for (const auto& [name, mesh] : nodes)
            if (name == node && mesh >= 0) return meshes.at(static_cast<std::size_t>(mesh));
        throw std::out_of_range("no node " + node + " with a mesh");
    }
    bool has_node(const std::string& node) const {
        for (const auto& n : nodes)
            if (n.first == node) return true;
        return false;
    }
};

AssimpInfo assimp_info(const fs::path& path) {
    const auto [status, output] = test::run_command("assimp info '" + path.string() + "' --raw");
    AssimpInfo info;
    info.raw = output;
    EXPECT_EQ(status, 0) << "is assimp-utils installed? " << output;
    std::istringstream in(output);
    std::string line;
    enum { None, Meshes, Materials, Nodes } section = None;
    const std::regex mesh_line(R"(^\s+\d+ \((.*)\): \[(\d+) / \d+ / (\d+) \|)");
    const std::regex material_line(R"(^\s+'(.+)' \(prop\))");
    const std::regex node_line(R"(^[^A-Za-z0-9_]*([A-Za-z0-9_]+)( \(mesh (\d+)\))?$)");
    while (std::getline(in, line)) {
        if (line.rfind("Meshes:  (name)", 0) == 0)
            section = Meshes;
        else if (line.rfind("Named Materials:", 0) == 0)
            section = Materials;
        else if (line.rfind("Node hierarchy:", 0) == 0)
            section = Nodes;
        std::smatch m;
        if (section == Meshes && std::regex_search(line, m, mesh_line))
            info.meshes.push_back({m[1], std::stoul(m[2]), std::stoul(m[3])});
        else if (section == Materials && std::regex_search(line, m, material_line))
            info.materials.push_back(m[1]);
        else if (section == Nodes && std::regex_search(line, m, node_line))
            info.nodes.push_back({m[1], m[3].matched ? std::stoi(m[3]) : -1});
    }
    return info;
}

// The JSON chunk of a .glb (after the 12-byte header and the 8-byte chunk header).
nlohmann::json glb_json(const std::string& bytes) {
    EXPECT_GE(bytes.size(), 20u);
    EXPECT_EQ(bytes.substr(0, 4), "glTF");
    std::uint32_t length = 0, json_length = 0;
    std::memcpy(&length, bytes.data() + 8, 4);
    std::memcpy(&json_length, bytes.data() + 12, 4);
    EXPECT_EQ(length, bytes.size());
    EXPECT_EQ(bytes.substr(16, 4), "JSON");
    return nlohmann::json::parse(bytes.substr(20, json_length));
}

TEST(ExportGlb, OpensInAssimpWithPartsMaterialsAndCounts) {
    const SmallTree& t = small_tree();
    const auto parts = t.parts();
    ASSERT_EQ(parts.size(), 3u) << "the default tree has trunk, crown and leaves";
    const fs::path path = temp_dir() / "tree.glb";
    EXPECT_EQ(write_model(path, parts), std::vector<fs::path>{path});

    const AssimpInfo info = assimp_info(path);
    ASSERT_EQ(info.meshes.size(), parts.size()) << info.raw;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        EXPECT_EQ(info.meshes[i].name, parts[i].name);
        EXPECT_EQ(info.meshes[i].faces, parts[i].mesh->triangles.size()) << parts[i].name;
        // Flat shading: three vertices of its own per triangle.
        EXPECT_EQ(info.meshes[i].vertices, 3 * parts[i].mesh->triangles.size()) << parts[i].name;
    }
    EXPECT_EQ(info.materials, (std::vector<std::string>{"trunk", "crown", "leaves"})) << info.raw;
    ASSERT_EQ(info.nodes.size(), 4u) << info.raw;
    EXPECT_EQ(info.nodes[0], (std::pair<std::string, int>{"tree", -1}));
    for (const NamedMesh& part : parts)
        EXPECT_EQ(info.mesh_of(part.name).faces, part.mesh->triangles.size()) << info.raw;
    fs::remove_all(path.parent_path());
}

TEST(ExportGlb, FlatShadingSplitsVerticesAndCarriesColours) {
    const SmallTree& t = small_tree();
    const auto parts = t.parts();
    std::ostringstream out;
    write_glb(out, parts, ExportOptions{});
    const nlohmann::json gltf = glb_json(out.str());
    EXPECT_EQ(gltf["asset"]["version"], "2.0");
    ASSERT_EQ(gltf["meshes"].size(), parts.size());
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const auto& primitive = gltf["meshes"][i]["primitives"][0];
        const std::size_t triangles = parts[i].mesh->triangles.size();
        EXPECT_EQ(gltf["accessors"][primitive["attributes"]["POSITION"].get<int>()]["count"],
                  3 * triangles);
        EXPECT_EQ(gltf["accessors"][primitive["indices"].get<int>()]["count"], 3 * triangles);
        const auto& material = gltf["materials"][primitive["material"].get<int>()];
        EXPECT_EQ(material["name"], parts[i].name);
        const auto& color = material["pbrMetallicRoughness"]["baseColorFactor"];
        EXPECT_NEAR(color[0].get<double>(), parts[i].color.r, 1e-6);
        EXPECT_NEAR(color[1].get<double>(), parts[i].color.g, 1e-6);
        EXPECT_NEAR(color[2].get<double>(), parts[i].color.b, 1e-6);
        EXPECT_EQ(material.value("doubleSided", false), !parts[i].closed);
    }
    // Smooth shading shares vertices, but for the copies split at creases.
    std::ostringstream smooth;
    write_glb(smooth, parts, ExportOptions{.shading = Shading::Smooth});
    const nlohmann::json s = glb_json(smooth.str());
    const auto& primitive = s["meshes"][0]["primitives"][0];
    EXPECT_EQ(s["accessors"][primitive["attributes"]["POSITION"].get<int>()]["count"],
              smooth_shaded(*parts[0].mesh).mesh.positions.size());
    EXPECT_LT(s["accessors"][primitive["attributes"]["POSITION"].get<int>()]["count"],
              3 * parts[0].mesh->triangles.size());
}

TEST(ExportGlb, SameInputSameBytes) {
    const auto parts = small_tree().parts();
    std::ostringstream a, b;
    write_glb(a, parts, ExportOptions{});
    write_glb(b, parts, ExportOptions{});
    EXPECT_EQ(a.str(), b.str());
}

// A minimal OBJ + MTL reader, independent of the writer: per group the faces, and the
// material each group uses; every index checked against what was declared before it.
struct ObjGroup {
    std::string material;
    std::size_t faces = 0;
    Mesh mesh;  // positions and triangles of this group only (0-based, local)
};
struct ObjFile {
    std::string mtllib;
    std::vector<std::string> group_order;
    std::map<std::string, ObjGroup> groups;
    std::size_t positions = 0, normals = 0;
    bool indices_valid = true;
    std::map<std::string, glm::vec3> kd;  // from the MTL
};

ObjFile read_obj_with_mtl(const fs::path& path) {
    ObjFile obj;
    std::ifstream in(path);
    std::string line, group, material;
    std::vector<glm::vec3> all_positions;
    std::map<std::string, std::map<std::size_t, std::uint32_t>> local;  // global -> local
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "mtllib")
            s >> obj.mtllib;
        else if (tag == "g") {
            s >> group;
            obj.group_order.push_back(group);
        } else if (tag == "usemtl") {
            s >> material;
            obj.groups[group].material = material;
        } else if (tag == "v") {
            glm::vec3 p;
            s >> p.x >> p.y >> p.z;
            all_positions.push_back(p);
            ++obj.positions;
        } else if (tag == "vn") {
            glm::vec3 n;
            s >> n.x >> n.y >> n.z;
            if (std::abs(glm::length(n) - 1.0f) > 1e-4f) obj.indices_valid = false;
            ++obj.normals;
        } else if (tag == "f") {
            ObjGroup& g = obj.groups[group];
            ++g.faces;
            std::array<std::uint32_t, 3> t{};
            for (int k = 0; k < 3; ++k) {
                std::string corner;
                s >> corner;
                const std::size_t slash = corner.find("//");
                const std::size_t v = std::stoul(corner.substr(0, slash));
                const std::size_t n =
                    slash == std::string::npos ? 0 : std::stoul(corner.substr(slash + 2));
                if (v < 1 || v > obj.positions ||
                    (slash != std::string::npos && (n < 1 || n > obj.normals)))
                    obj.indices_valid = false;
                auto [it, added] = local[group].try_emplace(
                    v, static_cast<std::uint32_t>(g.mesh.positions.size()));
                if (added) g.mesh.positions.push_back(all_positions[v - 1]);
                t[k] = it->second;
            }
            g.mesh.triangles.push_back(t);
        }
    }
    std::ifstream mtl(path.parent_path() / obj.mtllib);
    std::string name;
    while (std::getline(mtl, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "newmtl")
            s >> name;
        else if (tag == "Kd")
            s >> obj.kd[name].r >> obj.kd[name].g >> obj.kd[name].b;
    }
    return obj;
}

TEST(ExportObj, IndependentParserFindsGroupsMaterialsAndCounts) {
    const SmallTree& t = small_tree();
    const auto parts = t.parts();
    const fs::path path = temp_dir() / "tree.obj";
    const auto written = write_model(path, parts);
    EXPECT_EQ(written, (std::vector<fs::path>{path, temp_dir() / "tree.mtl"}));

    const ObjFile obj = read_obj_with_mtl(path);
    EXPECT_EQ(obj.mtllib, "tree.mtl");
    EXPECT_TRUE(obj.indices_valid);
    EXPECT_EQ(obj.group_order, (std::vector<std::string>{"trunk", "crown", "leaves"}));
    std::size_t faces = 0;
    for (const NamedMesh& part : parts) {
        SCOPED_TRACE(part.name);
        const ObjGroup& g = obj.groups.at(part.name);
        EXPECT_EQ(g.material, part.name);
        EXPECT_EQ(g.faces, part.mesh->triangles.size());
        EXPECT_EQ(g.mesh.positions.size(), part.mesh->positions.size());
        ASSERT_EQ(obj.kd.count(part.name), 1u);
        EXPECT_NEAR(glm::length(obj.kd.at(part.name) - part.color), 0.0f, 1e-6f);
        if (part.closed) {
            EXPECT_TRUE(check_topology(g.mesh).is_closed_manifold());
        }
        faces += part.mesh->triangles.size();
    }
    EXPECT_EQ(obj.normals, faces) << "flat shading: one normal per face";
    fs::remove_all(path.parent_path());
}

TEST(ExportObj, AssimpReadsTheSameGroupsAndMaterials) {
    const auto parts = small_tree().parts();
    const fs::path path = temp_dir() / "tree.obj";
    write_model(path, parts);
    const AssimpInfo info = assimp_info(path);
    ASSERT_EQ(info.meshes.size(), parts.size()) << info.raw;
    std::map<std::string, std::size_t> faces;
    for (const auto& m : info.meshes) faces[m.name] = m.faces;
    for (const NamedMesh& part : parts)
        EXPECT_EQ(faces[part.name], part.mesh->triangles.size()) << info.raw;
    for (const NamedMesh& part : parts)
        EXPECT_NE(std::find(info.materials.begin(), info.materials.end(), part.name),
                  info.materials.end())
            << part.name << "\n"
            << info.raw;
    fs::remove_all(path.parent_path());
}

TEST(ExportObj, SmoothShadingHasOneNormalPerVertex) {
    const auto parts = small_tree().parts();
    std::ostringstream out;
    write_obj_with_mtl(out, parts, ExportOptions{.shading = Shading::Smooth}, "x.mtl");
    std::size_t normals = 0, vertices = 0;
    std::istringstream in(out.str());
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("vn ", 0) == 0)
            ++normals;
        else if (line.rfind("v ", 0) == 0)
            ++vertices;
    }
    // Positions stay shared (the parts stay closed); normals split only at creases.
    std::size_t positions = 0, faces = 0;
    for (const NamedMesh& part : parts) {
        positions += part.mesh->positions.size();
        faces += part.mesh->triangles.size();
    }
    EXPECT_EQ(vertices, positions);
    EXPECT_GE(normals, vertices);
    EXPECT_LT(normals, 3 * faces);
}

TEST(ExportPly, HeaderAndBinaryBodyMatch) {
    const SmallTree& t = small_tree();
    const auto parts = t.parts();
    const fs::path path = temp_dir() / "tree.ply";
    write_model(path, parts);
    const std::string bytes = read_file(path);
    const std::size_t end = bytes.find("end_header\n");
    ASSERT_NE(end, std::string::npos);
    const std::string header = bytes.substr(0, end);
    std::size_t vertices = 0, faces = 0;
    for (const NamedMesh& p : parts) {
        vertices += p.mesh->positions.size();
        faces += p.mesh->triangles.size();
    }
    EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
    EXPECT_NE(header.find("element vertex " + std::to_string(vertices) + "\n"), std::string::npos);
    EXPECT_NE(header.find("element face " + std::to_string(faces) + "\n"), std::string::npos);
    // x y z (float) + r g b (uchar) per vertex; count (uchar) + 3 uint per face.
    EXPECT_EQ(bytes.size(), end + 11 + vertices * 15 + faces * 13);
    // The first vertex has the trunk's colour, sRGB-encoded.
    const auto* first = reinterpret_cast<const unsigned char*>(bytes.data() + end + 11);
    float x;
    std::memcpy(&x, first, 4);
    EXPECT_EQ(x, parts[0].mesh->positions[0].x);
    const float linear = parts[0].color.r;
    const float srgb =
        linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1 / 2.4f) - 0.055f;
    EXPECT_NEAR(first[12], srgb * 255.0f, 0.51f);
    fs::remove_all(path.parent_path());
}

TEST(ExportPly, AsciiOpensInAssimp) {
    const auto parts = small_tree().parts();
    const fs::path path = temp_dir() / "tree.ply";
    write_model(path, parts, ExportOptions{.ply_binary = false});
    const AssimpInfo info = assimp_info(path);
    std::size_t faces = 0;
    for (const NamedMesh& p : parts) faces += p.mesh->triangles.size();
    ASSERT_EQ(info.meshes.size(), 1u) << info.raw;
    EXPECT_EQ(info.meshes[0].faces, faces);
    fs::remove_all(path.parent_path());
}

TEST(ExportFormat, FollowsTheExtension) {
    EXPECT_EQ(format_from_extension("a/tree.OBJ"), &obj_format);
    EXPECT_EQ(format_from_extension("tree.glb"), &glb_format);
    EXPECT_EQ(format_from_extension("tree.ply"), &ply_format);
    EXPECT_EQ(format_from_extension("tree.stl"), nullptr);
    EXPECT_EQ(format_from_extension("tree"), nullptr);
    EXPECT_EQ(format_from_name("GLB"), &glb_format);
    EXPECT_EQ(ply_format.extension, ".ply");
    for (const ExportFormat* f : export_formats()) {
        EXPECT_EQ(format_from_name(f->name), f);
        EXPECT_EQ(format_from_extension("tree" + std::string(f->extension)), f);
    }

    const auto parts = small_tree().parts();
    const fs::path dir = temp_dir();
    try {
        write_model(dir / "tree.stl", parts);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("tree.stl"), std::string::npos) << e.what();
    }
    // An explicit format wins over the extension.
    write_model(dir / "tree.bin", parts, {}, &glb_format);
    EXPECT_EQ(read_file(dir / "tree.bin").substr(0, 4), "glTF");
    fs::remove_all(dir);
}

TEST(ExportErrors, NameThePathAndLeaveNothingBehind) {
    const auto parts = small_tree().parts();
    const fs::path dir = temp_dir();
    for (const char* name : {"tree.obj", "tree.glb", "tree.ply"}) {
        const fs::path path = dir / "missing" / name;
        try {
            write_model(path, parts);
            FAIL() << "expected IoError for " << name;
        } catch (const IoError& e) {
            EXPECT_NE(std::string(e.what()).find((dir / "missing").string()), std::string::npos)
                << e.what();
        }
    }
    EXPECT_FALSE(fs::exists(dir / "missing"));
    // An existing file stays intact when the new one cannot be written over it (a
    // directory in the way of the .obj).
    fs::create_directories(dir / "blocked.obj");
    EXPECT_THROW(write_model(dir / "blocked.obj", parts), IoError);
    EXPECT_FALSE(fs::exists(dir / "blocked.mtl")) << "the new MTL is taken back when the OBJ fails";
    fs::remove_all(dir);
}

// The small tree as `sylva export --lod` finishes it: four levels.
const FinishedTree& small_chain() {
    static const FinishedTree chain = [] {
        FinishSettings finish;
        finish.lod = true;
        return finish_tree(small_tree().tree, finish);
    }();
    return chain;
}

// The names in `dir`, sorted: what an export left behind (a staging folder shows as
// `.sylva-<pid>-<n>.tmp`).
std::vector<std::string> listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A full disk, simulated: a child process whose files cannot grow past 4 KiB writes an OBJ
// (about 100 KiB) whose .mtl (under 1 KiB) would fit: the failed OBJ must not leave the .mtl
// changed.
TEST(ExportAllOrNothing, AnObjThatFailsOnAFullDiskKeepsTheOldObjAndMtl) {
    const auto parts = small_tree().parts();
    const fs::path dir = temp_dir() / "full";
    fs::create_directories(dir);
    { std::ofstream(dir / "tree.obj") << "old obj\n"; }
    { std::ofstream(dir / "tree.mtl") << "old mtl\n"; }
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);  // EFBIG instead of death, as ENOSPC would be
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        try {
            write_model(dir / "tree.obj", parts);
        } catch (const IoError&) {
            ::_exit(4);
        }
        ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 4) << "the OBJ cannot fit";
    EXPECT_EQ(read_file(dir / "tree.obj"), "old obj\n");
    EXPECT_EQ(read_file(dir / "tree.mtl"), "old mtl\n");
    EXPECT_EQ(listing(dir), (std::vector<std::string>{"tree.mtl", "tree.obj"}));
    fs::remove_all(dir.parent_path());
}

// A chain whose third level cannot be written (a folder in its place) leaves no level, no
// .mtl and no staging folder, not LOD0, LOD1 and the .mtl of a half-written chain.
TEST(ExportAllOrNothing, AChainThatFailsAtLod2LeavesNoLevel) {
    const SmallTree& t = small_tree();
    for (const char* name : {"oak.obj", "oak.ply"}) {
        SCOPED_TRACE(name);
        const fs::path dir = temp_dir() / "chain";
        const fs::path path = dir / name;
        const fs::path lod2 = lod_file_names(path, 4)[2];
        fs::create_directories(lod2);
        try {
            write_tree(path, t.tree, small_chain(), t.colors);
            ADD_FAILURE() << "expected IoError";
        } catch (const IoError& e) {
            EXPECT_NE(std::string(e.what()).find(lod2.string()), std::string::npos) << e.what();
        }
        EXPECT_EQ(listing(dir), std::vector<std::string>{lod2.filename().string()});
        fs::remove_all(dir);
    }
    fs::remove_all(temp_dir());
}

// Through a symlink: the file it points to is replaced (the .mtl beside that file, named as
// the OBJ's mtllib says), the link stays a link.
TEST(ExportAllOrNothing, ASymlinkIsWrittenThrough) {
    const auto parts = small_tree().parts();
    const fs::path dir = temp_dir() / "link";
    fs::create_directories(dir / "real");
    { std::ofstream(dir / "real" / "tree.obj") << "old\n"; }
    fs::create_symlink("real/tree.obj", dir / "link.obj");
    const auto written = write_model(dir / "link.obj", parts);
    EXPECT_EQ(written,
              (std::vector<fs::path>{dir / "real" / "tree.obj", dir / "real" / "tree.mtl"}));
    EXPECT_TRUE(fs::is_symlink(dir / "link.obj"));
    EXPECT_EQ(read_obj_with_mtl(dir / "link.obj").mtllib, "tree.mtl");
    EXPECT_EQ(listing(dir), (std::vector<std::string>{"link.obj", "real"}));
    EXPECT_EQ(listing(dir / "real"), (std::vector<std::string>{"tree.mtl", "tree.obj"}));
    fs::remove_all(temp_dir());
}

TEST(ExportAllOrNothing, AFifoIsRefused) {
    const auto parts = small_tree().parts();
    // A FIFO of our own, never /dev/null: a regression run as root would replace the real
    // one (tests/core/test_file_set.cpp checks devices without writing).
    const fs::path dir = temp_dir() / "fifo";
    fs::create_directories(dir);
    ASSERT_EQ(::mkfifo((dir / "tree.glb").c_str(), 0600), 0);
    EXPECT_THROW(write_model(dir / "tree.glb", parts), IoError);
    EXPECT_TRUE(fs::is_fifo(dir / "tree.glb"));
    EXPECT_EQ(listing(dir), std::vector<std::string>{"tree.glb"});
    fs::remove_all(temp_dir());
}

const std::vector<std::string> kParts = {"trunk", "crown", "leaves"};

std::size_t suffixes(const std::string& name) {
    std::size_t count = 0;
    for (std::size_t at = name.find("_LOD"); at != std::string::npos;
         at = name.find("_LOD", at + 1))
        ++count;
    return count;
}

// Per part, its triangles at each level: never more at a coarser level; the leaves
// strictly fewer (thinned per level).
void expect_monotone(const std::map<std::string, std::vector<std::size_t>>& counts) {
    for (const auto& [part, levels] : counts)
        for (std::size_t i = 1; i < levels.size(); ++i) {
            EXPECT_LE(levels[i], levels[i - 1]) << part << " at LOD" << i;
            if (part == "leaves") {
                EXPECT_LT(levels[i], levels[i - 1]) << "LOD" << i;
            }
        }
}

TEST(ExportLod, BudgetsHalveForSolidsAndLeaves) {
    EXPECT_EQ(lod_budgets(800, 4), (std::vector<std::size_t>{800, 400, 200, 100}));
    const FinishedTree& chain = small_chain();
    EXPECT_EQ(chain.budgets, (std::vector<std::size_t>{800, 400, 200, 100}));
    EXPECT_EQ(chain.leaf_budgets, (std::vector<std::size_t>{800, 400, 200, 100}));
    ASSERT_EQ(chain.levels.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_LE(chain.levels[i].leaves.triangles.size(), chain.leaf_budgets[i]);
}

TEST(ExportLod, OneGlbWithOneSuffixPerNameAndThreeMaterials) {
    const SmallTree& t = small_tree();
    const fs::path path = temp_dir() / "tree.glb";
    EXPECT_EQ(write_tree(path, t.tree, small_chain(), t.colors), std::vector<fs::path>{path});
    const AssimpInfo info = assimp_info(path);
    std::map<std::string, std::vector<std::size_t>> counts;
    for (std::size_t i = 0; i < 4; ++i) {
        const std::string suffix = "_LOD" + std::to_string(i);
        EXPECT_TRUE(info.has_node("tree" + suffix)) << info.raw;
        for (const std::string& part : kParts)
            counts[part].push_back(info.mesh_of(part + suffix).faces);
    }
    for (const auto& [name, mesh] : info.nodes)
        EXPECT_EQ(suffixes(name), name == "tree" ? 0u : 1u) << name;
    expect_monotone(counts);
    EXPECT_EQ(info.materials, kParts) << "one material per part, shared by the levels";
    fs::remove_all(path.parent_path());
}

TEST(ExportLod, OneObjPerLevelGroundedWithOneMtl) {
    const SmallTree& t = small_tree();
    const fs::path dir = temp_dir();
    const auto written = write_tree(dir / "oak.obj", t.tree, small_chain(), t.colors);
    ASSERT_EQ(written,
              (std::vector<fs::path>{dir / "oak.mtl", dir / "oak_LOD0.obj", dir / "oak_LOD1.obj",
                                     dir / "oak_LOD2.obj", dir / "oak_LOD3.obj"}));
    std::map<std::string, std::vector<std::size_t>> counts;
    std::vector<float> ground;
    for (std::size_t i = 0; i < 4; ++i) {
        SCOPED_TRACE(i);
        const ObjFile obj = read_obj_with_mtl(written[i + 1]);
        EXPECT_EQ(obj.mtllib, "oak.mtl");
        EXPECT_TRUE(obj.indices_valid);
        EXPECT_EQ(obj.kd.size(), 3u) << "one shared material per part";
        const std::string suffix = "_LOD" + std::to_string(i);
        for (const std::string& part : kParts) {
            const ObjGroup& g = obj.groups.at(part + suffix);
            EXPECT_EQ(g.material, part) << "materials carry no suffix";
            EXPECT_EQ(obj.kd.count(part), 1u);
            counts[part].push_back(g.faces);
        }
        for (const std::string& group : obj.group_order) EXPECT_EQ(suffixes(group), 1u) << group;
        float low = std::numeric_limits<float>::max();
        for (const glm::vec3& p : obj.groups.at("trunk" + suffix).mesh.positions)
            low = std::min(low, p.y);
        ground.push_back(low);
    }
    expect_monotone(counts);
    for (float low : ground) EXPECT_NEAR(low, ground[0], 0.01f) << "every level on the ground";
    fs::remove_all(dir);
}

TEST(ExportLod, EveryLevelStandsWhereTheTreeStands) {
    // Seeds and a coarse mesh where independent reductions would lift LOD1's trunk.
    for (std::uint64_t seed : {1u, 2u, 3u, 7u}) {
        TreeTemplate tmpl = load_template("oak");
        tmpl.params.seed = seed;
        tmpl.params.trunk_resolution = 48;
        tmpl.params.crown_resolution = 32;
        const Tree tree = generate_tree(tmpl);
        float ground = std::numeric_limits<float>::max();
        for (const glm::vec3& p : tree.trunk.positions) ground = std::min(ground, p.y);
        const auto chain = make_lod_chain(tree, lod_budgets(TreeBudget{}, 4));
        for (std::size_t i = 0; i < chain.size(); ++i) {
            float low = std::numeric_limits<float>::max();
            for (const glm::vec3& p : chain[i].trunk.positions) low = std::min(low, p.y);
            EXPECT_NEAR(low, ground, 0.01f) << "seed " << seed << " LOD" << i;
            EXPECT_TRUE(check_topology(chain[i].trunk).is_closed_manifold());
        }
    }
}

// Sorted corner positions: the same for a duplicate face and a back-to-back copy.
std::array<std::array<float, 3>, 3> corners(const Mesh& mesh,
                                            const std::array<std::uint32_t, 3>& t) {
    std::array<std::array<float, 3>, 3> c;
    for (std::size_t k = 0; k < 3; ++k) {
        const glm::vec3& p = mesh.positions[t[k]];
        c[k] = {p.x, p.y, p.z};
    }
    std::sort(c.begin(), c.end());
    return c;
}

TEST(ExportLeaves, WrittenOnceWithoutBackToBackFaces) {
    const SmallTree& t = small_tree();
    const fs::path path = temp_dir() / "tree.obj";
    write_model(path, t.parts());
    const ObjFile obj = read_obj_with_mtl(path);
    const Mesh& leaves = obj.groups.at("leaves").mesh;
    ASSERT_GT(leaves.triangles.size(), 0u);
    EXPECT_EQ(leaves.triangles.size(), t.reduced.leaves.triangles.size());
    std::set<std::array<std::array<float, 3>, 3>> seen;
    for (const auto& tri : leaves.triangles)
        EXPECT_TRUE(seen.insert(corners(leaves, tri)).second) << "a duplicate or back copy";
    // glTF shows the single side from both sides through the material.
    std::ostringstream glb;
    write_glb(glb, t.parts(), ExportOptions{});
    const nlohmann::json gltf = glb_json(glb.str());
    EXPECT_TRUE(gltf["materials"][2]["doubleSided"].get<bool>());
    EXPECT_EQ(gltf["materials"][2]["name"], "leaves");
    fs::remove_all(path.parent_path());
}

TEST(ExportLeaves, TheBudgetThinsLeavesEvenlyAndGrowsThem) {
    const Tree& tree = small_tree().tree;
    const std::size_t all = count_leaves(tree.leaves);
    ASSERT_GT(all, 20u);
    const std::size_t budget = tree.leaves.triangles.size() / 4;
    const Mesh thin = thin_leaves(tree.leaves, budget);
    EXPECT_LE(thin.triangles.size(), budget);
    EXPECT_GT(thin.triangles.size(), budget * 3 / 4);
    const Mesh thinner = thin_leaves(tree.leaves, budget / 2);
    EXPECT_EQ(thin_leaves(tree.leaves, budget).positions, thin.positions) << "deterministic";
    // A coarser budget keeps a subset of the leaves: every kept base is a base of the finer.
    std::set<std::array<float, 3>> points;
    for (const glm::vec3& p : thin.positions) points.insert({p.x, p.y, p.z});
    std::size_t found = 0;
    for (const glm::vec3& p : thinner.positions) found += points.count({p.x, p.y, p.z});
    EXPECT_GT(found, 0u);
    // Even: the kept leaves' centre stays near the crown's leaves' centre.
    auto centre = [](const Mesh& m) {
        glm::dvec3 sum(0.0);
        for (const glm::vec3& p : m.positions) sum += glm::dvec3(p);
        return glm::vec3(sum / double(m.positions.size()));
    };
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& p : tree.leaves.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    EXPECT_LT(glm::length(centre(thin) - centre(tree.leaves)), 0.15f * glm::length(hi - lo));
    // Grown: the kept leaves cover about the same area (the growth is capped at 2x).
    auto area = [](const Mesh& m) {
        double a = 0.0;
        for (const auto& t : m.triangles)
            a += 0.5 * glm::length(glm::cross(m.positions[t[1]] - m.positions[t[0]],
                                              m.positions[t[2]] - m.positions[t[0]]));
        return a;
    };
    EXPECT_NEAR(area(thin), area(tree.leaves), 0.25 * area(tree.leaves));
    EXPECT_TRUE(thin_leaves(tree.leaves, 0).triangles.empty());
}

TEST(MeshNormals, SmoothNormalsFaceEveryTriangleOnEveryTemplate) {
    for (const TreeTemplate* tmpl : builtin_templates()) {
        SCOPED_TRACE(tmpl->name);
        const Tree tree = generate_tree(*tmpl);
        const ReducedTree reduced = reduce_tree(tree, TreeBudget{});
        for (const Mesh* part : {&reduced.trunk, &reduced.crown, &reduced.leaves}) {
            const ShadedMesh shaded = smooth_shaded(*part);
            ASSERT_EQ(shaded.mesh.triangles.size(), part->triangles.size());
            ASSERT_EQ(shaded.normals.size(), shaded.mesh.positions.size());
            const std::vector<glm::vec3> faces = face_normals(shaded.mesh);
            std::size_t bad = 0;
            for (std::size_t f = 0; f < faces.size(); ++f)
                for (std::uint32_t v : shaded.mesh.triangles[f]) {
                    EXPECT_NEAR(glm::length(shaded.normals[v]), 1.0f, 1e-4f);
                    if (faces[f] != glm::vec3(0.0f) &&
                        !(glm::dot(shaded.normals[v], faces[f]) > 0.0f))
                        ++bad;
                }
            EXPECT_EQ(bad, 0u) << "corners with a normal 90 degrees or more from their face";
        }
    }
}

TEST(MeshNormals, CreasesSplitACubeAndSmoothASphere) {
    // A cube: every corner meets three faces at 90 degrees, so each vertex splits in three
    // and every normal is its face's.
    Mesh cube;
    for (int i = 0; i < 8; ++i)
        cube.positions.push_back({float(i & 1), float(i >> 1 & 1), float(i >> 2 & 1)});
    cube.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                      {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    const ShadedMesh shaded = smooth_shaded(cube);
    EXPECT_EQ(shaded.mesh.positions.size(), 24u);
    const auto faces = face_normals(cube);
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (std::uint32_t v : shaded.mesh.triangles[f])
            EXPECT_NEAR(glm::dot(shaded.normals[v], faces[f]), 1.0f, 1e-5f);
    // Past the crease angle (here 100 degrees) the cube is one smooth blob again.
    EXPECT_EQ(smooth_shaded(cube, 100.0f).mesh.positions.size(), 8u);
}

TEST(MeshNormals, FaceAndVertexNormalsAreUnitAndOutward) {
    // A coarse sphere: every normal points away from the centre.
    ScalarField field = [](const glm::vec3& p) { return glm::length(p) - 1.0f; };
    MeshSettings settings;
    settings.resolution = 8;
    const Mesh trunk = marching_cubes(field, Box{glm::vec3(-1.0f), glm::vec3(1.0f)}, settings);
    const auto faces = face_normals(trunk);
    const auto vertices = vertex_normals(trunk);
    ASSERT_EQ(faces.size(), trunk.triangles.size());
    ASSERT_EQ(vertices.size(), trunk.positions.size());
    for (const glm::vec3& n : faces) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    for (const glm::vec3& n : vertices) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    for (std::size_t i = 0; i < vertices.size(); ++i)
        EXPECT_GT(glm::dot(vertices[i], glm::normalize(trunk.positions[i])), 0.9f);
    for (std::size_t f = 0; f < faces.size(); ++f)
        EXPECT_GT(glm::dot(faces[f], glm::normalize(trunk.positions[trunk.triangles[f][0]])), 0.5f);
}

}  // namespace
}  // namespace sylva
