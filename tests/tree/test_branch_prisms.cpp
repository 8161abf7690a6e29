// Branches as prisms on every built-in template: sound pieces, the budget kept, no branch
// drawn without the one it grows from, the trunk always drawn, straight runs one axis.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/mesh_checks.h"
#include "quality/self_intersections.h"
#include "tests/helpers.h"
#include "tree/branch_prisms.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

Skeleton chain_with_side_branch() {
    Skeleton s;
    s.segments.push_back({{0, 0, 0}, {0, 1, 0}, 0.2f, 0.18f, -1, 0});
    s.segments.push_back({{0, 1, 0}, {0, 2, 0}, 0.18f, 0.16f, 0, 0});
    s.segments.push_back({{0, 1, 0}, {0.8f, 1.6f, 0}, 0.05f, 0.03f, 0, 1});  // a side branch
    s.segments.push_back({{0, 2, 0}, {0.05f, 3, 0}, 0.16f, 0.1f, 1, 0});
    return s;
}

TEST(BranchPrisms, AStraightRunIsOneAxisAndABranchItsChild) {
    const Skeleton s = chain_with_side_branch();
    const BranchAxes axes = branch_axes(s, std::vector<std::uint8_t>(4, 1), 0.01f);
    ASSERT_EQ(axes.axes.size(), 2u);
    EXPECT_EQ(axes.axes[0].axis.points.size(), 4u);  // the trunk, through all three segments
    EXPECT_EQ(axes.axes[0].parent, -1);
    EXPECT_TRUE(axes.axes[0].axis.pointed);
    EXPECT_EQ(axes.axes[1].parent, 0);
    EXPECT_FLOAT_EQ(axes.thickest, 0.2f);
    // Radii below the thinnest drawn branch are raised to it.
    const BranchAxes widened = branch_axes(s, std::vector<std::uint8_t>(4, 1), 0.1f);
    EXPECT_FLOAT_EQ(widened.axes[1].axis.radii.back(), 0.1f);
    // A hidden segment's child hangs from its nearest shown ancestor's axis.
    const BranchAxes hidden = branch_axes(s, std::vector<std::uint8_t>{1, 0, 1, 1}, 0.01f);
    ASSERT_EQ(hidden.axes.size(), 2u);
    EXPECT_EQ(hidden.axes[0].axis.points.back(), s.segments[3].b);
    // A segment drawn twice (a bracket redrawing it) is drawn once.
    Skeleton twice = s;
    twice.segments.push_back(s.segments[2]);
    EXPECT_EQ(branch_axes(twice, std::vector<std::uint8_t>(5, 1), 0.01f).axes.size(), 2u);
}

// A branch gets sides in proportion to its radius (the thickest the look's most) unless
// fewer keep its polygon within half the look's tolerance of round: a twig that thin is a
// triangle, whatever the trunk's radius.
TEST(BranchPrisms, ATwigTheBudgetCannotShowRoundIsATriangle) {
    Skeleton s;
    s.segments.push_back({{0, 0, 0}, {0, 10, 0}, 0.5f, 0.5f, -1, 0});  // the trunk
    s.segments.push_back({{0, 5, 0}, {3, 5, 0}, 0.3f, 0.3f, 0, 1});    // a level branch
    const BranchAxes axes = branch_axes(s, std::vector<std::uint8_t>(2, 1), 0.001f);
    ASSERT_EQ(axes.axes.size(), 2u);
    const PrismLook look = prism_look(axes, 800);  // 0.04 m on a 10 m tree: a stray of 0.02
    ASSERT_EQ(look.max_sides, 6);
    ASSERT_NEAR(look.tolerance, 0.04f, 1e-6f);
    // The trunk ends in a cap (a branch grows from it), the branch, ten radii long, in a
    // short point (a ring before it: every axis is drawn and triangles are left).
    const auto triangles = [](int trunk_sides, int branch_sides) {
        return tube_triangles(2, trunk_sides, false) + tube_triangles(3, branch_sides, true);
    };
    // Radius 0.3: 6 x 0.6 = 3.6, 4 sides; round enough at 4 (pi / acos(1 - 0.02 / 0.3)
    // asks for 9).
    EXPECT_EQ(branch_prisms(axes, 800).mesh.triangles.size(), triangles(6, 4));
    // A trunk and a branch of 0.02 and 0.015: the radius rule gives 6 and 5, but
    // neither radius is above the stray: triangles.
    s.segments[0].ra = s.segments[0].rb = 0.02f;
    s.segments[1].ra = s.segments[1].rb = 0.015f;
    const BranchAxes thin = branch_axes(s, std::vector<std::uint8_t>(2, 1), 0.001f);
    EXPECT_EQ(branch_prisms(thin, 800).mesh.triangles.size(), triangles(3, 3));
    // At 3000 the look's tolerance is about half: 0.015 stays a triangle, 0.03 gets more.
    s.segments[0].ra = s.segments[0].rb = 0.03f;
    s.segments[1].ra = s.segments[1].rb = 0.03f;
    const BranchAxes finer = branch_axes(s, std::vector<std::uint8_t>(2, 1), 0.001f);
    EXPECT_GT(branch_prisms(finer, 3000).mesh.triangles.size(), triangles(3, 3));
}

// A pointed branch of one long segment: drawn with triangles to spare its point is short
// (the branch keeps its width to half a radius before its end, where a point over the whole
// segment thins it from the base); held to the plain prism's triangles, it is that prism.
TEST(BranchPrisms, ALongLastSegmentEndsInAShortPoint) {
    Skeleton s;
    s.segments.push_back({{0, 0, 0}, {0, 2, 0}, 0.1f, 0.1f, -1, 0});
    const BranchAxes axes = branch_axes(s, std::vector<std::uint8_t>(1, 1), 0.001f);
    ASSERT_EQ(axes.axes.size(), 1u);
    ASSERT_TRUE(axes.axes[0].axis.pointed);
    // The widest a vertex lies from the axis in the top tenth, below the point.
    const auto width_near_end = [](const Mesh& mesh) {
        float widest = 0.0f;
        for (const glm::vec3& p : mesh.positions)
            if (p.y > 1.8f && p.y < 2.0f) widest = std::max(widest, std::hypot(p.x, p.z));
        return widest;
    };
    const BranchPrisms free = branch_prisms(axes, 800);
    EXPECT_GE(width_near_end(free.mesh), 0.1f);
    const int sides = prism_look(axes, 800).max_sides;
    EXPECT_EQ(free.mesh.triangles.size(), tube_triangles(3, sides, true));
    const BranchPrisms held = branch_prisms(axes, 800, tube_triangles(2, sides, true));
    EXPECT_EQ(held.mesh.triangles.size(), tube_triangles(2, sides, true));
    EXPECT_LT(width_near_end(held.mesh), 0.05f);
    test::expect_closed_manifold(free.mesh);
}

// Where nothing hides a branch, a budget that cannot draw every axis at the look's
// tolerance but can draw each coarser draws them all (the largest first leaves some out).
TEST(BranchPrisms, EveryAxisFirstDrawsEveryAxisTheBudgetCanDrawCoarse) {
    MeshOptions options;
    options.budget = 200;
    const Tree tree = generate_tree(load_template("seed_spruce"), options);
    const BranchAxes& axes = tree.branch_axes;
    const std::size_t fewest = fewest_prism_triangles(axes, 200);
    ASSERT_GT(axes.axes.size(), 30u);
    const BranchPrisms every = branch_prisms(axes, 200, fewest, PrismOrder::EveryAxisFirst);
    EXPECT_EQ(every.left_out, 0u);
    EXPECT_LE(every.mesh.triangles.size(), fewest);
    EXPECT_GT(branch_prisms(axes, 200, fewest, PrismOrder::LargestFirst).left_out, 0u);
    // With more, the largest are refined: more triangles, every axis still drawn.
    const BranchPrisms more = branch_prisms(axes, 200, 2 * fewest, PrismOrder::EveryAxisFirst);
    EXPECT_EQ(more.left_out, 0u);
    EXPECT_GT(more.mesh.triangles.size(), every.mesh.triangles.size());
    EXPECT_LE(more.mesh.triangles.size(), 2 * fewest);
    EXPECT_TRUE(find_self_intersections(more.mesh).pairs.empty());
    test::expect_closed_manifold(more.mesh);
}

class PrismsOfTemplate : public ::testing::TestWithParam<std::string> {};

TEST_P(PrismsOfTemplate, AreSoundWithinTheirShareAndDrawParentsFirst) {
    MeshOptions options;
    options.budget = 800;
    const Tree tree = generate_tree(load_template(GetParam()), options);
    if (tree.branch_axes.axes.empty()) GTEST_SKIP() << "drawn as the trunk's surface";
    const BranchAxes& axes = tree.branch_axes;
    for (std::size_t budget : {50, 200, 800}) {
        for (std::size_t share : {std::size_t{1}, budget / 4, budget}) {
            const BranchPrisms prisms = branch_prisms(axes, budget, share);
            const std::string what =
                GetParam() + " at " + std::to_string(budget) + "/" + std::to_string(share);
            ASSERT_GT(prisms.drawn, 0u) << what << ": the trunk is always drawn";
            EXPECT_EQ(prisms.drawn + prisms.left_out, axes.axes.size()) << what;
            const MeshTopology topology = check_topology(prisms.mesh);
            EXPECT_TRUE(topology.is_closed_manifold()) << what << ": " << to_string(topology);
            for (double volume : component_volumes(prisms.mesh)) EXPECT_GT(volume, 0.0) << what;
            EXPECT_TRUE(find_self_intersections(prisms.mesh).pairs.empty()) << what;
            // Over the share only where the trunk alone needs more.
            if (prisms.drawn > 1 || share >= budget) {
                EXPECT_LE(prisms.mesh.triangles.size(), share) << what;
            }
        }
    }
    // Every axis, as the unreduced game mesh draws them, and fewer at smaller budgets.
    EXPECT_EQ(branch_prisms(axes, 800).left_out, 0u);
    EXPECT_LE(branch_prisms(axes, 200).mesh.triangles.size(),
              branch_prisms(axes, 800).mesh.triangles.size());
}

std::vector<std::string> template_names() {
    std::vector<std::string> names;
    for (const TreeTemplate* t : builtin_templates()) names.push_back(t->name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(EveryTemplate, PrismsOfTemplate, ::testing::ValuesIn(template_names()),
                         [](const auto& param) { return param.param; });

}  // namespace
}  // namespace sylva
