// Tree age (core/tree_age.h through the pipeline): a sweep of `age` over every built-in
// template grows it from seedling to the mature tree continuously: the height, the
// full-detail triangles (trunk + crown as meshed, the tree you see before a budget) and the
// game mesh's triangles (trunk + crown reduced to 800, plus its thinned leaves) never fall,
// and age 1 is the template's tree as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "core/tree_age.h"
#include "tree/growth.h"
#include "tree/lowpoly_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

float mesh_top(const Mesh& mesh, float top) {
    for (const glm::vec3& v : mesh.positions) top = std::max(top, v.y);
    return top;
}

struct Sample {
    double age;
    float height;
    size_t full;  // trunk + crown triangles as meshed
    size_t game;  // reduced trunk + crown + thinned leaves
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
            sweep.push_back({age, top, t.trunk.triangles.size() + t.crown.triangles.size(),
                             game.triangles + game.leaves.triangles.size()});
        }
        std::string shown;
        for (const Sample& s : sweep)
            shown += " [age " + std::to_string(s.age).substr(0, 3) + ": height " +
                     std::to_string(s.height) + ", full " + std::to_string(s.full) + ", game " +
                     std::to_string(s.game) + "]";
        std::printf("%s:%s\n", tree.name.c_str(), shown.c_str());
        for (size_t i = 1; i < sweep.size(); ++i) {
            EXPECT_GT(sweep[i].height, sweep[i - 1].height) << tree.name << shown;
            EXPECT_GT(sweep[i].full, sweep[i - 1].full) << tree.name << shown;
            EXPECT_GE(sweep[i].game, sweep[i - 1].game) << tree.name << shown;
        }
        // A seedling is small next to the grown tree.
        EXPECT_LT(sweep.front().height, 0.35f * sweep.back().height) << tree.name;
    }
}

}  // namespace
}  // namespace sylva
