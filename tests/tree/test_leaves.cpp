// Leaves: placed only inside the crown, as many as the density asks, the same for the same
// seed, and each shape drawn from both sides.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "marching/mesh_checks.h"
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
    const std::size_t per_leaf = outline == 4 ? 4 : 2 * outline;  // both sides
    EXPECT_EQ(leaves.triangles.size() % per_leaf, 0u);
    return leaves.triangles.size() / per_leaf;
}

TEST(Leaves, TheSeedsLeafIsTwoTrianglesUpAndTwoDown) {
    LeafSettings s;
    s.density = 5;
    Mesh leaves = scatter_leaves(ball, kBox, s);
    ASSERT_GT(leaves.triangles.size(), 0u);
    // Triangles come in pairs with opposite winding over the same three vertices.
    for (size_t t = 0; t + 1 < leaves.triangles.size(); t += 2) {
        auto up = leaves.triangles[t], down = leaves.triangles[t + 1];
        EXPECT_EQ(up[0], down[0]);
        EXPECT_EQ(up[1], down[2]);
        EXPECT_EQ(up[2], down[1]);
    }
    EXPECT_EQ(leaves.triangles.size() % 4, 0u);
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
    TreeTemplate t = load_template("spruce");
    t.params.crown_mesh = 0;
    t.params.leaf_density = 500;
    Tree leaves_only = generate_tree(t);
    EXPECT_TRUE(leaves_only.crown.triangles.empty());
    EXPECT_GT(leaves_only.leaves.triangles.size(), 0u);

    t.params.crown_mesh = 1;
    t.params.crown_blend = static_cast<int>(CrownBlend::Pasko);
    t.params.crown_fusion = 0.05;
    Tree pasko = generate_tree(t);
    EXPECT_GT(pasko.crown.triangles.size(), 0u);
    EXPECT_TRUE(check_topology(pasko.crown).is_closed_manifold())
        << to_string(check_topology(pasko.crown));
}

TEST(TrunkJoints, BlendRadiusAddsMaterialAndStaysClosed) {
    TreeTemplate t = load_template("spruce");
    Tree hard = generate_tree(t);
    t.params.joint_blend = 0.05;
    Tree blended = generate_tree(t);
    EXPECT_TRUE(check_topology(blended.trunk).is_closed_manifold());
    EXPECT_GT(enclosed_volume(blended.trunk), enclosed_volume(hard.trunk));
}

}  // namespace
}  // namespace sylva
