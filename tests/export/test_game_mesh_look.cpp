// The look of game meshes (quality/): every template's crown, at game budgets and in a LOD
// chain, has no faces crossing inside a piece and at most 2% of its edge length folding
// inwards sharper than a right angle; a trunk's faces cross only where the reduction says
// the budget left it no other way; and the guard is what keeps them apart.
#include <gtest/gtest.h>

#include <string>

#include "export/export_tree.h"
#include "quality/folds.h"
#include "quality/self_intersections.h"
#include "tree/lowpoly_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

FinishedTree game_mesh(const TreeTemplate& tmpl, std::size_t budget, bool lod,
                       bool keep_apart = true) {
    FinishSettings finish;
    finish.budget.total = budget;
    finish.lod = lod;
    finish.decimate.keep_apart = keep_apart;
    MeshOptions mesh;
    mesh.budget = game_budget(finish);
    return finish_tree(generate_tree(tmpl, mesh), finish);
}

TEST(GameMeshLook, CrownsNeitherCrossNorFoldAtEveryBudgetAndLevel) {
    for (const TreeTemplate* tmpl : builtin_templates())
        for (const std::size_t budget : {200, 800, 3000}) {
            const FinishedTree finished = game_mesh(*tmpl, budget, budget == 800);
            for (std::size_t level = 0; level < finished.levels.size(); ++level) {
                const ReducedTree& r = finished.levels[level];
                const std::string at = tmpl->name + " at " + std::to_string(budget) + " level " +
                                       std::to_string(level);
                EXPECT_EQ(self_intersecting_pairs(r.crown), 0u) << at;
                EXPECT_LE(concave_fold_share(r.crown), 0.02) << at;
                if (r.crossing_pairs == 0) {
                    EXPECT_EQ(self_intersecting_pairs(r.trunk), 0u) << at;
                }
            }
        }
}

// The fir's trunk, reduced without the guard, folds through itself at 800.
TEST(GameMeshLook, TheGuardKeepsATrunkApartThatWouldCross) {
    TreeTemplate fir = load_template("fir");
    fir.params.branch_style = BranchStyle::Surface;  // meshed, not drawn
    const ReducedTree loose = game_mesh(fir, 800, false, false).levels.front();
    const ReducedTree kept = game_mesh(fir, 800, false).levels.front();
    EXPECT_GT(self_intersecting_pairs(loose.trunk), 0u);
    EXPECT_EQ(kept.crossing_pairs, 0u);
    EXPECT_EQ(self_intersecting_pairs(kept.trunk), 0u);
    EXPECT_EQ(kept.triangles, 800u);
}

}  // namespace
}  // namespace sylva
