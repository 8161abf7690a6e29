// The pipeline end to end: the default tree becomes a closed mesh, its OBJ reads back as
// the same closed mesh, parameters are validated, and failed writes leave nothing behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <glm/vector_relational.hpp>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/mesh_checks.h"
#include "export/obj_writer.h"
#include "tree/parameters.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"
#include "turtle/lsystem_params.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

// p lies more than `depth` inside some segment's cone (radii at least 0.9 cells, as the
// trunk's field widens them).
bool inside_a_branch(const Skeleton& skeleton, const glm::vec3& p, float cell, float depth) {
    return std::any_of(skeleton.segments.begin(), skeleton.segments.end(), [&](const Segment& s) {
        const glm::vec3 axis = s.b - s.a;
        const float t = std::clamp(glm::dot(p - s.a, axis) / std::max(glm::dot(axis, axis), 1e-12f),
                                   0.0f, 1.0f);
        const float r = std::max(s.ra + t * (s.rb - s.ra), 0.9f * cell);
        return glm::distance(p, s.a + t * axis) < r - depth;
    });
}

// Points bucketed for "is one of them within `reach` of p".
class NearPoints {
  public:
    NearPoints(const std::vector<glm::vec3>& points, float reach) : reach_(reach) {
        for (const glm::vec3& p : points) buckets_.emplace(key(p, 0, 0, 0), p);
    }
    bool operator()(const glm::vec3& p) const {
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto [first, last] = buckets_.equal_range(key(p, dx, dy, dz));
                    for (auto it = first; it != last; ++it)
                        if (glm::distance(it->second, p) <= reach_) return true;
                }
        return false;
    }

  private:
    std::int64_t key(const glm::vec3& p, int dx, int dy, int dz) const {
        const glm::ivec3 k = glm::ivec3(glm::floor(p / reach_)) + glm::ivec3(dx, dy, dz);
        return (std::int64_t(k.x) * 73856093) ^ (std::int64_t(k.y) * 19349663) ^
               (std::int64_t(k.z) * 83492791);
    }
    float reach_;
    std::unordered_multimap<std::int64_t, glm::vec3> buckets_;
};

// A deliberately independent, minimal OBJ reader: "v x y z" and "f a b c" lines.
Mesh read_obj(const fs::path& path) {
    Mesh mesh;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "v") {
            glm::vec3 p;
            s >> p.x >> p.y >> p.z;
            mesh.positions.push_back(p);
        } else if (tag == "f") {
            std::array<std::uint32_t, 3> t;
            s >> t[0] >> t[1] >> t[2];
            for (auto& i : t) --i;
            mesh.triangles.push_back(t);
        }
    }
    return mesh;
}

fs::path temp_dir() {
    fs::path dir = fs::temp_directory_path() / ("sylva_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

TEST(Pipeline, DefaultTreeIsAClosedMeshThatSurvivesTheObjRoundTrip) {
    Tree tree = generate_tree(default_template());
    EXPECT_GT(tree.skeleton.segments.size(), 100u);
    EXPECT_GT(tree.trunk.triangles.size(), 1000u);
    MeshTopology topology = check_topology(tree.trunk);
    EXPECT_TRUE(topology.is_closed_manifold())
        << "boundary " << topology.boundary_edges << ", non-manifold "
        << topology.non_manifold_edges << ", misoriented " << topology.misoriented_edges
        << ", degenerate " << topology.degenerate_triangles;
    EXPECT_GT(enclosed_volume(tree.trunk), 0.0);

    fs::path path = temp_dir() / "default.obj";
    write_obj(path, {{"trunk", &tree.trunk}});
    Mesh back = read_obj(path);
    EXPECT_EQ(back.triangles.size(), tree.trunk.triangles.size());
    EXPECT_EQ(back.positions.size(), tree.trunk.positions.size());
    EXPECT_TRUE(check_topology(back).is_closed_manifold());
    fs::remove_all(path.parent_path());
}

TEST(Pipeline, TheMeshHugsTheSkeleton) {
    // The mesh stays within a cell or two of the skeleton's box and starts at the trunk's base:
    // no stray geometry, nothing clipped at the bottom.
    Tree tree = generate_tree(default_template());
    Box box = skeleton_bounds(tree.skeleton);
    glm::vec3 extent = box.max - box.min;
    float cell = std::max({extent.x, extent.y, extent.z}) /
                 static_cast<float>(default_template().params.trunk_resolution);
    float lowest = std::numeric_limits<float>::max();
    for (const glm::vec3& p : tree.trunk.positions) {
        lowest = std::min(lowest, p.y);
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, box.min - glm::vec3(2 * cell))));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(p, box.max + glm::vec3(2 * cell))));
    }
    EXPECT_NEAR(lowest, tree.skeleton.segments.front().a.y, cell);  // the trunk's base
}

// A game mesh's trunk leaves out what the crown hides (drop_hidden, the willow's default):
// every part of the full trunk that shows outside the crown's spheres (the trunk and the
// main branches) is still there, within two cells, and the hidden twigs are gone (fewer raw
// triangles for the reduction). Checked to fail when branches under 1.5 cells are dropped.
TEST(Pipeline, AGameMeshLeavesOutOnlyTheBranchesTheCrownHides) {
    TreeTemplate willow = load_template("willow");
    ASSERT_TRUE(willow.params.drop_hidden);
    willow.params.branch_style = BranchStyle::Surface;  // meshed, not drawn
    MeshOptions game;
    game.budget = 800;
    const Tree kept = generate_tree(willow, game);
    willow.params.drop_hidden = false;
    const Tree full = generate_tree(willow, game);
    EXPECT_GT(kept.hidden_segments, 0u);
    EXPECT_LT(kept.trunk.triangles.size(), 0.85 * full.trunk.triangles.size());

    const Box box = skeleton_bounds(full.skeleton);
    const glm::vec3 extent = box.max - box.min;
    const float cell = std::max({extent.x, extent.y, extent.z}) /
                       static_cast<float>(willow.params.trunk_resolution);
    // Within two cells of the kept trunk's vertices.
    const NearPoints near_kept(kept.trunk.positions, 2.0f * cell);
    const std::vector<Ball> crown = crown_spheres(full.skeleton, willow.params);
    const float margin = static_cast<float>(willow.params.crown_fusion) + 1.0f * cell;
    std::size_t shown = 0, lost = 0;
    for (const glm::vec3& p : full.trunk.positions) {
        const bool in_crown = std::any_of(crown.begin(), crown.end(), [&](const Ball& b) {
            return glm::distance(p, b.center) < b.radius + margin;
        });
        // A game mesh's trunk is several solids that overlap where they meet (trunk_pieces in
        // tree/trunk_pieces.h): a branch's base inside its parent is no part of the surface.
        if (in_crown || inside_a_branch(full.skeleton, p, cell, cell)) continue;
        ++shown;
        if (!near_kept(p)) ++lost;
    }
    EXPECT_GT(shown, 300u);  // the test sees the trunk and the main branches
    EXPECT_EQ(lost, 0u) << "of " << shown << " trunk vertices outside the crown";
}

// A game mesh's large trunk comes in pieces (tree/trunk_pieces.h, so that the
// reduction works on both cores): several closed solids with the one-field trunk's surface
// (the bush meshes at its template's resolution with a budget and without). Every vertex of
// the one-field trunk has a piece's vertex within a cell and a half, and every piece's
// vertex lies as near that surface or inside a branch, where a piece's base meets its
// parent. Checked to fail when a group's segments are left out (its branches are lost).
TEST(Pipeline, AGameMeshTrunkComesInPiecesWithTheSameSurface) {
    TreeTemplate bush = load_template("bush");
    bush.params.branch_style = BranchStyle::Surface;  // meshed, not drawn
    MeshOptions game;
    game.budget = 800;
    const Tree pieces = generate_tree(bush, game);
    const Tree whole = generate_tree(bush);
    EXPECT_GE(component_volumes(pieces.trunk).size(), component_volumes(whole.trunk).size() + 2);
    EXPECT_TRUE(check_topology(pieces.trunk).is_closed_manifold());
    for (double v : component_volumes(pieces.trunk)) EXPECT_GT(v, 0.0);

    const Box box = skeleton_bounds(whole.skeleton);
    const glm::vec3 extent = box.max - box.min;
    const float cell =
        std::max({extent.x, extent.y, extent.z}) / static_cast<float>(bush.params.trunk_resolution);
    // Marching cubes puts vertices on the cells' edges: within a cell and a half of every
    // point of its surface.
    const NearPoints near_piece(pieces.trunk.positions, 1.5f * cell);
    const NearPoints near_whole(whole.trunk.positions, 1.5f * cell);
    std::size_t lost = 0, astray = 0;
    for (const glm::vec3& p : whole.trunk.positions) lost += near_piece(p) ? 0 : 1;
    for (const glm::vec3& p : pieces.trunk.positions)
        astray += near_whole(p) || inside_a_branch(whole.skeleton, p, cell, 0.5f * cell) ? 0 : 1;
    EXPECT_EQ(lost, 0u) << "of " << whole.trunk.positions.size();
    EXPECT_EQ(astray, 0u) << "of " << pieces.trunk.positions.size();
}

TEST(Pipeline, StagesMadeBesideEachOtherCountOnceInTheWallTime) {
    // The trunk mesh, the crown mesh and the leaves overlap: the longest of them counts.
    const std::vector<StageTime> times = {{"derive", 1.0},           {"turtle", 0.5},
                                          {"fields", 2.0},           {"trunk mesh", 5.0, true},
                                          {"crown mesh", 7.0, true}, {"leaves", 3.0, true}};
    EXPECT_DOUBLE_EQ(stages_wall_ms(times), 1.0 + 0.5 + 2.0 + 7.0);
    const Tree tree = generate_tree(load_template("ternary"));
    double sum = 0.0, longest = 0.0;
    for (const StageTime& stage : tree.times) {
        sum += stage.ms;
        longest = std::max(longest, stage.ms);
    }
    EXPECT_LT(stages_wall_ms(tree.times), sum);  // the pipeline marks the stages it overlaps
    EXPECT_GE(stages_wall_ms(tree.times), longest);
}

TEST(Pipeline, SameInputsGiveTheSameBytes) {
    Tree a = generate_tree(default_template()), b = generate_tree(default_template());
    std::ostringstream oa, ob;
    write_obj(oa, {{"trunk", &a.trunk}});
    write_obj(ob, {{"trunk", &b.trunk}});
    EXPECT_EQ(oa.str(), ob.str());
}

TEST(Pipeline, ParametersChangeTheTree) {
    TreeTemplate t = default_template();
    t.params.blocks.edit<LSystemParams>().generations = 3;
    t.params.trunk_resolution = 32;
    Tree small = generate_tree(t);
    t.params.blocks.edit<LSystemParams>().generations = 4;
    Tree bigger = generate_tree(t);
    EXPECT_GT(bigger.skeleton.segments.size(), small.skeleton.segments.size());
}

TEST(Pipeline, AGrammarThatDrawsNothingIsAnInputError) {
    TreeTemplate t = default_template();
    t.grammar = "axiom: A\nA -> B\n";
    EXPECT_THROW(generate_tree(t), InputError);
    t.grammar = "axiom: F\nF -> F[+F\n";
    EXPECT_THROW(generate_tree(t), GrammarError);
}

TEST(Params, BadValuesAreRejectedNamingKeyAndRange) {
    TreeParams p;
    for (const char* bad : {"nan", "inf", "-1", "abc", "", "1e9"}) {
        try {
            set_param(p, "trunk_taper", bad);
            ADD_FAILURE() << bad;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("trunk_taper"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("0 to 1"), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW(set_param(p, "generations", "2.5"), InputError);
    EXPECT_THROW(set_param(p, "no_such_key", "1"), InputError);
    set_param(p, "trunk_taper", "0.5");
    EXPECT_EQ(lsystem_params(p).trunk_taper, 0.5);
    EXPECT_EQ(*get_param(p, "trunk_taper"), 0.5);
}

TEST(Export, UnwritablePathIsAnIoErrorAndLeavesNoFile) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    fs::path missing_dir = temp_dir() / "no" / "such" / "dir" / "tree.obj";
    EXPECT_THROW(write_obj(missing_dir, {{"trunk", &mesh}}), IoError);
    EXPECT_FALSE(fs::exists(missing_dir.parent_path()));
    fs::remove_all(temp_dir());
}

TEST(Export, AFailedWriteKeepsThePreviousFile) {
    fs::path dir = temp_dir();
    fs::path path = dir / "tree.obj";
    { std::ofstream(path) << "previous\n"; }
    auto fails_midway = [](std::ostream& out) {
        out << "half a file";
        throw IoError("disk full (simulated)");
    };
    EXPECT_THROW(write_file_atomically(path, fails_midway), IoError);
    std::ifstream in(path);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first, "previous");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1)
        << "no temporary file is left behind";
    fs::remove_all(dir);
}

TEST(Templates, NamesFilesAndUnknowns) {
    EXPECT_EQ(load_template("default").name, default_template().name);
    EXPECT_EQ(load_template("spruce").name, "spruce");
    EXPECT_THROW(load_template("no-such-tree"), InputError);
    fs::path dir = temp_dir();
    fs::path grammar = dir / "bush.lsys";
    { std::ofstream(grammar) << "axiom: F\nF -> F[+F]F\n"; }
    TreeTemplate t = load_template(grammar.string());
    EXPECT_EQ(t.grammar, "axiom: F\nF -> F[+F]F\n");
    EXPECT_THROW(load_template(dir.string()), IoError);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
