// Tree age (core/tree_age.h through the pipeline): a sweep of `age` over every built-in
// template grows it from seedling to the mature tree continuously: the skeleton's top and
// the full-detail triangles (trunk + crown as meshed, the tree you see before a budget) rise
// strictly, the game mesh's triangles (trunk + crown reduced to 800, plus its thinned leaves)
// never fall, and the height with the crown and the meshes' top never fall by more than
// a sliver (see below); the seedling is small.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "core/tree_age.h"
#include "tree/growth.h"
#include "tree/leaf_thinning.h"
#include "tree/lowpoly_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

float mesh_top(const Mesh& mesh, float top) {
    for (const glm::vec3& v : mesh.positions) top = std::max(top, v.y);
    return top;
}

// The top of the skeleton's segments, radii included.
float skeleton_top(const Skeleton& skeleton) {
    float top = std::numeric_limits<float>::lowest();
    for (const Segment& s : skeleton.segments) top = std::max({top, s.a.y + s.ra, s.b.y + s.rb});
    return top;
}

// The tree's height as grown: the top of its segments and of its (age-scaled) crown spheres.
float grown_height(const Skeleton& skeleton, TreeParams p) {
    float top = skeleton_top(skeleton);
    p.sphere_diameter *= crown_scale_at_age(p.age);
    p.crown_offset *= crown_scale_at_age(p.age);
    if (p.sphere_diameter > 0.0)
        for (const Ball& ball : crown_spheres(skeleton, p))
            top = std::max(top, ball.center.y + ball.radius);
    return top;
}

struct Sample {
    double age;
    float skeleton;  // skeleton_top()
    float height;    // grown_height()
    float mesh_top;  // the meshes' highest vertex
    size_t full;     // trunk + crown triangles as meshed
    size_t game;     // reduced trunk + crown
    size_t leaves;   // leaves (or leaf cards) of the game mesh
};

TEST(TemplateAge, EveryTemplateGrowsMonotonicallyInHeightAndTriangles) {
    const std::vector<double> ages = {0.0, 0.2, 0.4, 0.6, 0.8, 1.0};
    for (const TreeTemplate* builtin : builtin_templates()) {
        TreeTemplate tree = *builtin;
        // A coarse grid keeps the sweep fast; the age scales it like any other resolution.
        tree.params.trunk_resolution = std::min(tree.params.trunk_resolution, 48);
        tree.params.crown_resolution = std::min(tree.params.crown_resolution, 32);
        std::vector<Sample> sweep;
        for (const double age : ages) {
            tree.params.age = age;
            const Tree t = generate_tree(tree);
            const ReducedTree game = reduce_tree(t, TreeBudget{});
            const float top =
                mesh_top(t.crown, mesh_top(t.trunk, std::numeric_limits<float>::lowest()));
            sweep.push_back({age, skeleton_top(t.skeleton), grown_height(t.skeleton, tree.params),
                             top, t.trunk.triangles.size() + t.crown.triangles.size(),
                             game.triangles, count_leaves(game.leaves)});
        }
        std::string shown;
        for (const Sample& s : sweep)
            shown += " [age " + std::to_string(s.age).substr(0, 3) + ": height " +
                     std::to_string(s.height) + ", mesh top " + std::to_string(s.mesh_top) +
                     ", full " + std::to_string(s.full) + ", game " + std::to_string(s.game) +
                     ", leaves " + std::to_string(s.leaves) + "]";
        std::printf("%s:%s\n", tree.name.c_str(), shown.c_str());
        for (size_t i = 1; i < sweep.size(); ++i) {
            // Branches only grow: the skeleton rises strictly. Crown spheres sit at the tips,
            // and a tip the front passes hands its sphere to the tips beyond it, which may
            // stand a little lower: the grown height never falls by more than 0.5 % of the
            // mature height.
            EXPECT_GT(sweep[i].skeleton, sweep[i - 1].skeleton) << tree.name << shown;
            EXPECT_GT(sweep[i].height, sweep[i - 1].height - 0.005f * sweep.back().height)
                << tree.name << shown;
            // The meshes sample the grown shape on a grid: their top may wobble within a cell
            // (the crown's cells are the coarser), never more.
            const float cell =
                sweep.back().height / static_cast<float>(tree.params.crown_resolution);
            EXPECT_GT(sweep[i].mesh_top, sweep[i - 1].mesh_top - cell) << tree.name << shown;
            EXPECT_GT(sweep[i].full, sweep[i - 1].full) << tree.name << shown;
            // The game mesh keeps what it had: as many trunk + crown triangles, and (within the
            // leaf cards' grid, 2 % of the cards the budget buys) as many leaves.
            EXPECT_GE(sweep[i].game, sweep[i - 1].game) << tree.name << shown;
            EXPECT_GE(sweep[i].leaves + kDefaultTriangleBudget / 2 / 50, sweep[i - 1].leaves)
                << tree.name << shown;
        }
        // A seedling is small next to the grown tree.
        EXPECT_LT(sweep.front().height, 0.15f * sweep.back().height) << tree.name;
    }
}

}  // namespace
}  // namespace sylva
