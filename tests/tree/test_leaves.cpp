// Leaves: placed only inside the crown, as many as the density asks, the same for the same
// seed, each leaf written once (one-sided: the material shows the back).
#include <gtest/gtest.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <set>

#include "core/mesh_checks.h"
#include "core/random.h"
#include "tree/growth.h"
#include "tree/leaves.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

// A ball of radius 2 at the origin as the crown.
float ball(const glm::vec3& p) {
    return glm::length(p) - 2.0f;
}
const Box kBox{glm::vec3(-2.5f), glm::vec3(2.5f)};

std::size_t leaf_count(const Mesh& leaves, LeafShape shape) {
    const std::size_t outline = leaf_outline(shape).size();
    const std::size_t per_leaf = outline == 4 ? 2 : outline;  // one side
    EXPECT_EQ(leaves.triangles.size() % per_leaf, 0u);
    return leaves.triangles.size() / per_leaf;
}

// The three corner positions of a triangle, sorted: equal for a duplicate and for a
// back-to-back copy (same corners, opposite winding), whatever vertices they use.
std::array<std::array<float, 3>, 3> corners(const Mesh& mesh,
                                            const std::array<std::uint32_t, 3>& t) {
    std::array<std::array<float, 3>, 3> c;
    for (int k = 0; k < 3; ++k) {
        const glm::vec3& p = mesh.positions[t[static_cast<std::size_t>(k)]];
        c[static_cast<std::size_t>(k)] = {p.x, p.y, p.z};
    }
    std::sort(c.begin(), c.end());
    return c;
}

void expect_each_face_once(const Mesh& leaves) {
    std::set<std::array<std::array<float, 3>, 3>> seen;
    for (const auto& t : leaves.triangles)
        EXPECT_TRUE(seen.insert(corners(leaves, t)).second) << "a duplicate or back-to-back face";
}

TEST(Leaves, TheSeedsLeafIsTwoTrianglesWrittenOnce) {
    LeafSettings s;
    s.density = 5;
    Mesh leaves = scatter_leaves(ball, kBox, s);
    ASSERT_GT(leaves.triangles.size(), 0u);
    EXPECT_EQ(leaves.triangles.size() % 2, 0u);
    EXPECT_EQ(leaves.positions.size(), 2 * leaves.triangles.size()) << "four corners, two faces";
    expect_each_face_once(leaves);
    for (LeafShape shape : {LeafShape::Oak, LeafShape::Needle, LeafShape::Frond}) {
        s.shape = shape;
        expect_each_face_once(scatter_leaves(ball, kBox, s));
    }
}

TEST(Leaves, PolygonsAreFannedOnce) {
    Mesh leaves;
    add_polygon_leaves(leaves, {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-0.5f, 0.5f, 0}},
                                {{2, 0, 0}, {3, 0, 0}},  // too few corners: skipped
                                {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}});
    EXPECT_EQ(leaves.triangles.size(), 3u + 1u);
    expect_each_face_once(leaves);
    // One winding: every face of the flat polygons points the same way (+z).
    for (const auto& t : leaves.triangles) {
        const glm::vec3 n = glm::cross(leaves.positions[t[1]] - leaves.positions[t[0]],
                                       leaves.positions[t[2]] - leaves.positions[t[0]]);
        EXPECT_GT(n.z, 0.0f);
    }
}

TEST(Leaves, CountFollowsTheDensityAndLeavesSitInsideTheCrown) {
    const double volume = 4.0 / 3.0 * std::numbers::pi * 8.0;  // the ball's
    for (double density : {2.0, 10.0, 40.0}) {
        LeafSettings s;
        s.density = density;
        s.size = 0.1;
        Mesh leaves = scatter_leaves(ball, kBox, s);
        double count = double(leaf_count(leaves, s.shape));
        EXPECT_NEAR(count, density * volume, 0.15 * density * volume + 3) << density;
        // Every leaf starts inside the crown; its far end is at most a leaf length out.
        for (const glm::vec3& p : leaves.positions) EXPECT_LT(ball(p), 0.13f);
    }
}

TEST(Leaves, SameSeedSameLeavesOtherSeedOtherLeaves) {
    LeafSettings s;
    s.density = 10;
    Mesh a = scatter_leaves(ball, kBox, s), b = scatter_leaves(ball, kBox, s);
    s.seed = 2;
    Mesh c = scatter_leaves(ball, kBox, s);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_NE(a.positions, c.positions);
}

// The grid's slabs are scattered on a core each, each cell skipping the random numbers the
// cells before it draw: one thread or many, the same leaves in the same order.
TEST(Leaves, TheSameLeavesOnOneCoreAsOnMany) {
    Random drawn(7), skipped(7);
    for (int i = 0; i < 1000; ++i) drawn.next();
    skipped.discard(1000);
    EXPECT_EQ(drawn.next(), skipped.next());

    LeafSettings s;
    s.density = 20;
    s.shape = LeafShape::Oak;
    const Mesh many = scatter_leaves(ball, kBox, s);
    Mesh one;
    tbb::task_arena single(1);
    single.execute([&] { one = scatter_leaves(ball, kBox, s); });
    ASSERT_GT(many.triangles.size(), 100u);
    EXPECT_EQ(one.positions, many.positions);
    EXPECT_EQ(one.triangles, many.triangles);
}

// A crown's field is a distance bound, so the scatter skips blocks of the grid whose centre
// lies farther outside than the block reaches: the same leaves, in the same order, from a
// third to a half fewer samples. On real crowns, both as the pipeline wears them (a shell one leaf
// deep under the crown's surface) and filled (the crown not meshed).
TEST(Leaves, SkippingSpaceOutsideTheCrownKeepsEveryLeaf) {
    for (const char* name : {"oak", "spruce", "willow", "ternary"}) {
        const TreeTemplate t = load_template(name);
        const TreeFields fields = tree_fields(grow(t), t.params);
        ASSERT_TRUE(fields.crown) << name;
        const SphereField& crown = *fields.crown;
        ASSERT_TRUE(crown.is_distance_bound()) << name;
        const float shell = static_cast<float>(t.params.leaf_size);
        const auto in_shell = [&crown, shell](const glm::vec3& q) {
            return std::abs(crown(q) + 0.5f * shell) - 0.5f * shell;
        };
        const auto in_crown = [&crown](const glm::vec3& q) { return crown(q); };
        for (const bool worn : {true, false}) {
            std::atomic<std::size_t> samples{0};
            const auto counted = [&](const glm::vec3& q) {
                ++samples;
                return worn ? in_shell(q) : in_crown(q);
            };
            LeafSettings s;
            s.density = t.params.leaf_density;
            s.size = t.params.leaf_size;
            const Mesh every = scatter_leaves(counted, fields.crown_box, s);
            const std::size_t all_samples = samples.exchange(0);
            s.inside_is_distance_bound = true;
            const Mesh skipped = scatter_leaves(counted, fields.crown_box, s);
            ASSERT_GT(every.triangles.size(), 100u) << name;
            EXPECT_EQ(skipped.positions, every.positions) << name << (worn ? " shell" : "");
            EXPECT_EQ(skipped.triangles, every.triangles) << name << (worn ? " shell" : "");
            if (worn) {
                EXPECT_LT(3 * samples.load(), 2 * all_samples) << name;
            }
        }
    }
}

TEST(Leaves, EveryShapeAndTheCapHold) {
    for (LeafShape shape :
         {LeafShape::Round, LeafShape::Oak, LeafShape::Needle, LeafShape::Frond}) {
        LeafSettings s;
        s.density = 5;
        s.shape = shape;
        Mesh leaves = scatter_leaves(ball, kBox, s);
        EXPECT_GT(leaf_count(leaves, shape), 50u);
    }
    LeafSettings many;
    many.density = 20000;
    many.max_leaves = 1000;
    EXPECT_LE(leaf_count(scatter_leaves(ball, kBox, many), many.shape), 1000u);
}

TEST(Leaves, LeavesOnlyModeAndPaskoCrown) {
    TreeTemplate t = load_template("seed_spruce");
    t.params.crown_mesh = false;
    t.params.leaf_density = 500;
    Tree leaves_only = generate_tree(t);
    EXPECT_TRUE(leaves_only.crown.triangles.empty());
    EXPECT_GT(leaves_only.leaves.triangles.size(), 0u);

    t.params.crown_mesh = true;
    t.params.crown_blend = CrownBlend::Pasko;
    t.params.crown_fusion = 0.05;
    Tree pasko = generate_tree(t);
    EXPECT_GT(pasko.crown.triangles.size(), 0u);
    EXPECT_TRUE(check_topology(pasko.crown).is_closed_manifold())
        << to_string(check_topology(pasko.crown));
}

TEST(TrunkJoints, BlendRadiusAddsMaterialAndStaysClosed) {
    TreeTemplate t = load_template("seed_spruce");
    Tree hard = generate_tree(t);
    t.params.joint_blend = 0.05;
    Tree blended = generate_tree(t);
    EXPECT_TRUE(check_topology(blended.trunk).is_closed_manifold());
    EXPECT_GT(enclosed_volume(blended.trunk), enclosed_volume(hard.trunk));
}

}  // namespace
}  // namespace sylva
