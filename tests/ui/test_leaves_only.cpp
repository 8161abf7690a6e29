// A leaf edit in the studio scatters new leaves over the shown tree instead of growing and
// meshing again: the leaves must be the very bytes the pipeline makes for the edit, for
// L-system and colonization trees, with a meshed crown (leaves in a shell) and without one.
#include <gtest/gtest.h>

#include <string>

#include "tree/parameters.h"
#include "tree/template_library.h"
#include "turtle/lsystem_params.h"
#include "ui/state/leaves_only.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {
namespace {

TreeTemplate coarse(const std::string& name) {
    TreeTemplate t = load_template(name);
    t.params.trunk_resolution = 32;
    t.params.crown_resolution = 24;
    return t;
}

MeshOptions options_for(const TreeTemplate& t) {
    MeshOptions options;
    options.budget = static_cast<std::size_t>(t.params.triangle_budget);  // as the studio
    return options;
}

TEST(LeavesOnly, OnlyLeafParametersMakeALeafEdit) {
    const TreeTemplate oak = coarse("oak");
    TreeTemplate edit = oak;
    edit.params.leaf_density *= 2.0;
    edit.params.leaf_size *= 1.5;
    edit.params.leaf_shape =
        static_cast<LeafShape>((static_cast<int>(oak.params.leaf_shape) + 1) % 4);
    edit.colors.leaves = {1.0f, 0.0f, 0.0f};
    EXPECT_TRUE(leaves_only_edit(oak, edit));
    EXPECT_TRUE(leaves_only_edit(oak, oak));
    for (const char* key : {"tropism", "sphere_diameter", "crown_resolution", "triangle_budget"}) {
        TreeTemplate other = edit;
        set_param(other.params, key, *get_param(other.params, key) + 1.0);
        EXPECT_FALSE(leaves_only_edit(oak, other)) << key;
    }
    TreeTemplate seeded = edit;
    seeded.params.seed += 1;  // rand() in the rules: another skeleton
    EXPECT_FALSE(leaves_only_edit(oak, seeded));
    TreeTemplate regrown = edit;
    regrown.grammar += "\n";
    EXPECT_FALSE(leaves_only_edit(oak, regrown));
}

TEST(LeavesOnly, NewLeavesAreThePipelinesOwn) {
    for (const char* name : {"oak", "willow", "elm", "bush"}) {
        for (const bool crown_mesh : {true, false}) {
            TreeTemplate before = coarse(name);
            before.params.crown_mesh = crown_mesh;
            if (std::string(name) == "willow")
                before.params.blocks.edit<LSystemParams>().generations = 7;
            const Tree shown = generate_tree(before, options_for(before));
            TreeTemplate edit = before;
            edit.params.leaf_density = before.params.leaf_density * 1.7 + 10.0;
            edit.params.leaf_size *= 0.8;
            edit.params.leaf_shape =
                static_cast<LeafShape>((static_cast<int>(before.params.leaf_shape) + 1) % 4);
            ASSERT_TRUE(leaves_only_edit(before, edit));
            const std::optional<Tree> quick = with_new_leaves(shown, edit);
            ASSERT_TRUE(quick) << name;
            const Tree full = generate_tree(edit, options_for(edit));
            EXPECT_TRUE(same_mesh(quick->leaves, full.leaves))
                << name << " crown_mesh " << crown_mesh;
            // The bush's leaves are the turtle's polygons alone: no leaf parameter moves them.
            if (std::string(name) != "bush") {
                EXPECT_NE(quick->leaves.triangles.size(), shown.leaves.triangles.size()) << name;
            }
            EXPECT_TRUE(same_mesh(quick->trunk, full.trunk)) << name;
            EXPECT_TRUE(same_mesh(quick->crown, full.crown)) << name;
        }
    }
}

TEST(LeavesOnly, AYoungerTreeIsGrownAgain) {
    TreeTemplate young = coarse("oak");
    young.params.age = 0.5;
    const Tree shown = generate_tree(young, options_for(young));
    TreeTemplate edit = young;
    edit.params.leaf_density *= 2.0;
    EXPECT_FALSE(with_new_leaves(shown, edit));
}

TEST(LeavesOnly, TheStudioScattersLeavesAndKeepsTheReduction) {
    StudioState state;
    state.tree_template = state.committed = coarse("oak");
    state.tree_template.params.triangle_budget = 300;
    state.view.low_poly = true;
    start_generation(state);
    const auto wait = [&state] {
        while (generation_running(state)) poll_jobs(state);
    };
    wait();
    ASSERT_TRUE(state.tree && state.tree->reduced());
    const auto before = state.tree;
    state.tree_template.params.leaf_size *= 1.3;
    start_generation(state);
    ASSERT_TRUE(state.job);
    EXPECT_EQ(state.job->leaves_base, before);
    wait();
    ASSERT_TRUE(state.tree->reduced());
    EXPECT_TRUE(state.tree->reduction_reused);
    EXPECT_TRUE(same_mesh(state.tree->tree.trunk, before->tree.trunk));
    EXPECT_FALSE(same_mesh(state.tree->tree.leaves, before->tree.leaves));
    EXPECT_EQ(state.tree->tree.skeleton.segments.size(), before->tree.skeleton.segments.size());
}

}  // namespace
}  // namespace sylva::studio
