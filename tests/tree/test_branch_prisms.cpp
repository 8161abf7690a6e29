// Branches as prisms on every built-in template: sound pieces, the budget kept, no branch
// drawn without the one it grows from, the trunk always drawn, straight runs one axis.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/mesh_checks.h"
#include "quality/self_intersections.h"
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
