// The game mesh is sound at every budget: random parameters x every template x every mesher
// x budgets from 50 to 3000, made the way `sylva export` makes it. Every trunk and crown
// is a closed 2-manifold without degenerate triangles, and every piece of it encloses a
// positive volume (nothing inside out, no token part); no faces of a piece cross but where
// the reduction counted them, and a crown folds inwards by under 2% from 200 triangles on.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/mesh_checks.h"
#include "core/random.h"
#include "export/export_tree.h"
#include "quality/folds.h"
#include "quality/self_intersections.h"
#include "tree/parameters.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"
#include "turtle/lsystem_params.h"

namespace sylva {
namespace {

// `key` scaled by a random factor in [1 - spread, 1 + spread], kept in its range.
void jitter(TreeParams& params, std::string_view key, double spread, Random& random) {
    for (const ParamInfo& info : param_infos()) {
        if (info.key != key) continue;
        const double value =
            *get_param(params, key) * (1.0 + spread * (2.0 * random.uniform() - 1.0));
        set_param(params, key, std::clamp(value, info.min, info.max));
    }
}

// The template with random shape parameters at a coarse grid (so a hundred reductions stay
// fast); the same seed gives the same tree.
TreeTemplate randomized(const TreeTemplate& base, std::uint64_t seed) {
    Random random(seed);
    TreeTemplate t = base;
    t.params.seed = 1 + random.next() % 1000;
    for (const char* key : {"pitch_angle", "yaw_angle", "sphere_diameter", "crown_fusion",
                            "branch_width", "leaf_density"})
        jitter(t.params, key, 0.3, random);
    double& tropism = t.params.blocks.edit<LSystemParams>().tropism;
    tropism = std::clamp(tropism + 0.2 * (random.uniform() - 0.5), -1.0, 1.0);
    t.params.trunk_resolution = 24 + static_cast<int>(random.next() % 33);
    t.params.crown_resolution = 24 + static_cast<int>(random.next() % 33);
    return t;
}

void expect_sound(const Mesh& part, const std::string& what) {
    if (part.triangles.empty()) return;
    const MeshTopology topology = check_topology(part);
    EXPECT_TRUE(topology.is_closed_manifold()) << what << ": " << to_string(topology);
    for (double volume : component_volumes(part))
        EXPECT_GT(volume, 0.0) << what << ": a piece is inside out or has no volume";
}

class GameMeshSoundness : public ::testing::TestWithParam<std::string> {};

TEST_P(GameMeshSoundness, EveryPartIsClosedAndOutwardAtEveryBudgetAndMesher) {
    const TreeTemplate base = load_template(GetParam());
    std::uint64_t seed = std::hash<std::string>{}(GetParam()) % 1000;
    for (Mesher mesher : {Mesher::Sparse, Mesher::Dense, Mesher::Vdb}) {
        const TreeTemplate t = randomized(base, ++seed);
        for (std::size_t budget : {50, 200, 800, 3000}) {
            FinishSettings finish;
            finish.budget.total = budget;
            MeshOptions options;
            options.mesher = mesher;
            options.budget = game_budget(finish);
            const Tree tree = generate_tree(t, options);
            const FinishedTree finished = finish_tree(tree, finish);
            ASSERT_EQ(finished.levels.size(), 1u);
            const std::string what = GetParam() + " seed " + std::to_string(seed) + " mesher " +
                                     std::to_string(static_cast<int>(mesher)) + " budget " +
                                     std::to_string(budget);
            const ReducedTree& reduced = finished.levels[0];
            expect_sound(reduced.trunk, what + " trunk");
            expect_sound(reduced.crown, what + " crown");
            // Faces cross inside a piece only where the reduction counted (and said) it;
            // crowns do not fold into spikes.
            if (reduced.crossing_pairs == 0) {
                EXPECT_EQ(self_intersecting_pairs(reduced.trunk), 0u) << what << " trunk";
                EXPECT_EQ(self_intersecting_pairs(reduced.crown), 0u) << what << " crown";
            }
            if (budget >= 200) {
                EXPECT_LE(concave_fold_share(reduced.crown), 0.02) << what << " crown";
            }
            EXPECT_FALSE(reduced.trunk.triangles.empty()) << what << ": the trunk vanished";
            if (!tree.crown.triangles.empty()) {
                EXPECT_FALSE(reduced.crown.triangles.empty()) << what << ": the crown vanished";
            }
        }
    }
}

std::vector<std::string> template_names() {
    std::vector<std::string> names;
    for (const TreeTemplate* t : builtin_templates()) names.push_back(t->name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(Templates, GameMeshSoundness, ::testing::ValuesIn(template_names()),
                         [](const auto& param_info) { return param_info.param; });

// The honda at 100 triangles: a trunk of real rings (not four triangles turned inside out)
// and a crown of a few pieces (not dozens of separate tetrahedra).
TEST(GameMesh, HondaAtALowBudgetHasARealTrunkAndAFewCrownPieces) {
    FinishSettings finish;
    finish.budget.total = 100;
    MeshOptions options;
    options.budget = game_budget(finish);
    const Tree tree = generate_tree(load_template("honda"), options);
    EXPECT_GT(tree.crown_bridges, 0u) << "the crown's blobs were not bridged";
    const FinishedTree finished = finish_tree(tree, finish);
    const ReducedTree& reduced = finished.levels.at(0);
    expect_sound(reduced.trunk, "trunk");
    expect_sound(reduced.crown, "crown");
    EXPECT_GE(reduced.trunk.triangles.size(), 20u) << "a token trunk";
    EXPECT_LE(component_volumes(reduced.crown).size(), 100u / 2 / 8);
    EXPECT_LE(reduced.triangles, 110u);
}

}  // namespace
}  // namespace sylva
