// The low-poly stage on real trees: the default tree reduced to game budgets stays closed
// and manifold part by part, hits the budget where its topology allows, says why where it
// does not, and strays further from the fine surface the harder it is reduced.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <limits>

#include "core/mesh_checks.h"
#include "export/export_tree.h"
#include "lowpoly/merge_meshes.h"
#include "tree/lowpoly_tree.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

// Coarse meshing keeps the test fast; the shapes are the default tree's.
TreeTemplate coarse_default() {
    TreeTemplate t = default_template();
    t.params.trunk_resolution = 48;
    t.params.crown_resolution = 32;
    return t;
}

TreeBudget total(std::size_t triangles) {
    TreeBudget b;
    b.total = triangles;
    return b;
}

const Tree& coarse_tree() {
    static const Tree tree = generate_tree(coarse_default());
    return tree;
}

void expect_closed(const Mesh& mesh, const char* part) {
    if (mesh.triangles.empty()) return;
    const MeshTopology t = check_topology(mesh);
    EXPECT_TRUE(t.is_closed_manifold())
        << part << ": boundary " << t.boundary_edges << ", non-manifold edges "
        << t.non_manifold_edges << ", misoriented " << t.misoriented_edges << ", degenerate "
        << t.degenerate_triangles << ", non-manifold vertices " << t.non_manifold_vertices;
    EXPECT_GT(enclosed_volume(mesh), 0.0) << part;
}

TEST(TreeReduction, ClosedAtEveryBudgetAndOnBudgetAboveTheFloor) {
    const Tree& tree = coarse_tree();
    ASSERT_FALSE(tree.crown.triangles.empty());
    // The fewest triangles this tree's topology allows (its trunk has handles where
    // branches cross): what an impossible budget gives.
    const ReducedTree floor = reduce_tree(tree, total(4));
    EXPECT_FALSE(floor.within_budget);
    EXPECT_FALSE(floor.note.empty());
    expect_closed(floor.trunk, "trunk");
    expect_closed(floor.crown, "crown");

    for (std::size_t budget : {50u, 100u, 200u, 400u, 800u}) {
        SCOPED_TRACE(budget);
        const ReducedTree r = reduce_tree(tree, total(budget));
        expect_closed(r.trunk, "trunk");
        expect_closed(r.crown, "crown");
        EXPECT_EQ(r.triangles, r.trunk.triangles.size() + r.crown.triangles.size());
        EXPECT_FALSE(r.crown.triangles.empty()) << "no part vanishes";
        EXPECT_EQ(r.backoffs, 0) << r.note;
        if (budget >= floor.triangles + 2) {
            EXPECT_TRUE(r.within_budget) << r.note;
            EXPECT_LE(r.triangles, budget);
            EXPECT_GE(r.triangles, budget - 2);  // a collapse removes two triangles
        } else {
            EXPECT_FALSE(r.within_budget);
            EXPECT_FALSE(r.note.empty());
            EXPECT_LE(r.triangles, floor.triangles + 8);
        }
    }
}

TEST(TreeReduction, BudgetPerPart) {
    const Tree& tree = coarse_tree();
    TreeBudget budget;
    budget.total = 900;
    budget.crown = 200;                      // the trunk gets the remaining 700
    budget.crown_shape = CrownShape::Blobs;  // hulls may have fewer triangles than the budget
    const ReducedTree r = reduce_tree(tree, budget);
    EXPECT_LE(r.crown.triangles.size(), 200u);
    EXPECT_GE(r.crown.triangles.size(), 198u);
    EXPECT_LE(r.trunk.triangles.size(), 700u);
    EXPECT_GE(r.trunk.triangles.size(), 698u);
    expect_closed(r.trunk, "trunk");
    expect_closed(r.crown, "crown");
}

TEST(TreeReduction, FidelityGrowsWithReduction) {
    const Tree& tree = coarse_tree();
    // The reference here is the tree's own coarse surface (the benchmark uses the
    // resolution-200 one): then every error comes from the reduction alone.
    const Mesh* parts[] = {&tree.trunk, &tree.crown};
    Mesh reference;
    for (const Mesh* m : parts) {
        const auto base = static_cast<std::uint32_t>(reference.positions.size());
        reference.positions.insert(reference.positions.end(), m->positions.begin(),
                                   m->positions.end());
        for (const auto& t : m->triangles)
            reference.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    float lo = 1e30f, hi = -1e30f;
    for (const glm::vec3& p : reference.positions) {
        lo = std::min(lo, p.y);
        hi = std::max(hi, p.y);
    }
    const Fidelity identical = measure_tree_fidelity(tree.trunk, tree.crown, reference);
    EXPECT_LT(identical.mean_percent, 1e-4);
    double previous = identical.mean_percent, at_game_budget = 0.0;
    for (std::size_t budget : {3000u, 800u, 300u}) {
        const ReducedTree r = reduce_tree(tree, total(budget));
        const Fidelity f = measure_tree_fidelity(r.trunk, r.crown, reference);
        EXPECT_GT(f.mean_percent, previous) << budget;
        EXPECT_GE(f.max_percent, f.mean_percent);
        EXPECT_NEAR(f.height, hi - lo, 1e-5);
        previous = f.mean_percent;
        if (budget == 800) at_game_budget = f.mean_percent;
    }
    // A game budget stays close to the surface it came from.
    EXPECT_LT(at_game_budget, 1.0);
}

// The forward measure sees only where the game mesh strays; the loss (the other way round)
// sees a part it dropped: a tree without its crown is all on the full surface, yet the
// crown's surface is far from it.
TEST(TreeReduction, TheLossSeesWhatTheGameMeshDropped) {
    const Tree& tree = coarse_tree();
    const Mesh* parts[] = {&tree.trunk, &tree.crown};
    const Mesh reference = merge_meshes(parts);
    const Mesh none;
    const Fidelity kept = measure_tree_fidelity(tree.trunk, none, reference);
    EXPECT_LT(kept.mean_percent, 1e-4);
    const Fidelity lost = measure_tree_loss(tree.trunk, none, reference, kept.height);
    EXPECT_GT(lost.mean_percent, 1.0);
    EXPECT_LT(measure_tree_loss(tree.trunk, tree.crown, reference, kept.height).mean_percent, 1e-4);
}

// The crown is meshed as fine as its budget can show (docs/lowpoly.md, "Meshed for the budget"): 24
// cells at 200 and below, 2 sqrt(budget / 2) up to 800 (40), then growing with the budget's
// fourth root (56 at 3000, where the square root would give 78), never finer than the
// template's and never coarser as the budget grows; no budget keeps the template's.
TEST(TreeReduction, TheCrownIsMeshedAsFineAsItsBudgetCanShow) {
    EXPECT_EQ(crown_resolution_for_budget(200, 0), 200);
    EXPECT_EQ(crown_resolution_for_budget(200, 100), 24);
    EXPECT_EQ(crown_resolution_for_budget(200, 200), 24);
    EXPECT_EQ(crown_resolution_for_budget(200, 800), 40);
    EXPECT_EQ(crown_resolution_for_budget(200, 3000), 56);
    EXPECT_EQ(crown_resolution_for_budget(48, 3000), 48);
    int previous = 0;
    for (std::size_t budget = 50; budget <= 20000; budget += 50) {
        const int cells = crown_resolution_for_budget(1000, budget);
        EXPECT_GE(cells, previous) << budget;
        EXPECT_GE(cells, 24) << budget;
        const double square_root_law = 2.0 * std::sqrt(static_cast<double>(budget) / 2.0);
        if (budget > kTrunkDetailBudget) {
            EXPECT_LT(cells, square_root_law) << budget;
        }
        previous = cells;
    }
}

// Below 800 triangles a game mesh meshes the trunk coarser (trunk_resolution_for_budget,
// half the template's cells at 200) and loses nothing the budget could show: the bush (no
// crown, so its trunk is the whole budget and the cost) at 200 starts from at most half the
// raw triangles, and its game mesh strays about as far from the fine surface, either way,
// as the one reduced from the template's resolution (the mean error within 10% of it, the
// Hausdorff distance under 22% of the height).
TEST(TreeReduction, ASmallBudgetMeshesTheTrunkAsCoarseAsItCanShow) {
    TreeTemplate bush = load_template("bush");
    bush.params.branch_style = BranchStyle::Surface;  // meshed, not drawn
    EXPECT_EQ(trunk_resolution_for_budget(bush.params, 0), bush.params.trunk_resolution);
    EXPECT_EQ(trunk_resolution_for_budget(bush.params, 800), bush.params.trunk_resolution);
    EXPECT_EQ(trunk_resolution_for_budget(bush.params, 3000), bush.params.trunk_resolution);
    EXPECT_EQ(trunk_resolution_for_budget(bush.params, 200),
              (bush.params.trunk_resolution + 1) / 2);
    EXPECT_EQ(trunk_resolution_for_budget(bush.params, 10), 24);  // the floor

    MeshOptions game;
    game.budget = 200;
    const Tree coarse = generate_tree(bush, game);
    TreeTemplate as_before = bush;  // twice the cells, halved again: the template's own
    as_before.params.trunk_resolution = 2 * bush.params.trunk_resolution;
    const Tree fine = generate_tree(as_before, game);
    EXPECT_LT(coarse.trunk.triangles.size(), fine.trunk.triangles.size() / 2);

    const Mesh reference = reference_surface(bush, 200);
    auto both_ways = [&](const Tree& tree) {
        const ReducedTree game_mesh = reduce_tree(tree, total(200));
        expect_closed(game_mesh.trunk, "trunk");
        const Fidelity there = measure_tree_fidelity(game_mesh.trunk, game_mesh.crown, reference);
        const Fidelity back =
            measure_tree_loss(game_mesh.trunk, game_mesh.crown, reference, there.height);
        return std::pair{there.mean_percent + back.mean_percent,
                         std::max(there.max_percent, back.max_percent)};
    };
    const auto [coarse_mean, coarse_hausdorff] = both_ways(coarse);
    const auto [fine_mean, fine_hausdorff] = both_ways(fine);
    EXPECT_LT(coarse_mean, 1.1 * fine_mean);
    EXPECT_LT(coarse_hausdorff, 22.0);
}

TEST(TreeReduction, ReferenceSurfaceIsFinerAndClosed) {
    TreeTemplate tmpl = coarse_default();
    const Mesh fine = reference_surface(tmpl, 64);
    EXPECT_GT(fine.triangles.size(), coarse_tree().trunk.triangles.size());
    expect_closed(fine, "reference");
}

TEST(TreeReduction, PartsForExport) {
    const Tree& tree = coarse_tree();
    const PartColors colors;
    const auto parts = tree_parts(tree.trunk, tree.crown, tree.leaves, colors);
    ASSERT_EQ(parts.size(), tree.leaves.triangles.empty() ? 2u : 3u);
    EXPECT_EQ(parts[0].name, "trunk");
    EXPECT_EQ(parts[0].color, colors.trunk);
    EXPECT_TRUE(parts[0].closed);
    EXPECT_EQ(parts[1].name, "crown");
    if (parts.size() == 3) {
        EXPECT_EQ(parts[2].name, "leaves");
        EXPECT_FALSE(parts[2].closed);
    }
    EXPECT_EQ(tree_parts(tree.trunk, Mesh{}, Mesh{}, colors).size(), 1u);
}

// The horizontal extent of what lies within 1% of the height above the lowest point: where
// the trunk meets the ground.
float footprint(const Mesh& trunk) {
    float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
    for (const glm::vec3& p : trunk.positions) {
        low = std::min(low, p.y);
        high = std::max(high, p.y);
    }
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : trunk.positions)
        if (p.y <= low + 0.01f * (high - low)) {
            lo = glm::min(lo, glm::vec2(p.x, p.z));
            hi = glm::max(hi, glm::vec2(p.x, p.z));
        }
    return std::max(hi.x - lo.x, hi.y - lo.y);
}

// A thin trunk's base ring is cheap to collapse: the elm and the ternary tree stood on a
// single vertex at 800 triangles, their lowest 4 m a cone to a point. The foot stays.
TEST(TreeReduction, TheTrunkKeepsItsFootAtEveryBudgetAndLevel) {
    for (const char* name : {"elm", "ternary"}) {
        const Tree tree = generate_tree(load_template(name));
        const float raw = footprint(tree.trunk);
        ASSERT_GT(raw, 0.1f) << name;
        for (std::size_t budget : {100u, 800u}) {
            const ReducedTree r = reduce_tree(tree, total(budget));
            EXPECT_GT(footprint(r.trunk), 0.7f * raw) << name << " at " << budget;
        }
        const std::vector<TreeBudget> budgets = lod_budgets(total(800), 4);
        for (const ReducedTree& level : make_lod_chain(tree, budgets))
            EXPECT_GT(footprint(level.trunk), 0.7f * raw) << name << " LOD " << level.triangles;
    }
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

bool same_mesh_bytes(const Mesh& a, const Mesh& b) {
    return a.positions == b.positions && a.triangles == b.triangles;
}

// The studio shows level 0 before the chain's coarser levels are made: a chain continued
// from the level finish_tree() made alone is the chain made in one go (the willow's coarser
// levels draw the crown as hulls, the path that costs most).
TEST(TreeReduction, AChainFromItsLevelZeroIsTheWholeChain) {
    MeshOptions options;
    options.budget = 800;
    const Tree tree = generate_tree(load_template("willow"), options);
    FinishSettings chain;
    chain.budget.total = 800;
    chain.lod = true;
    FinishSettings alone = chain;
    alone.lod = false;
    FinishedTree first = finish_tree(tree, alone);
    ASSERT_EQ(first.levels.size(), 1u);
    const FinishedTree whole = finish_tree(tree, chain);
    const FinishedTree continued = finish_tree(tree, chain, std::move(first.levels[0]));
    ASSERT_EQ(whole.levels.size(), continued.levels.size());
    EXPECT_EQ(whole.budgets, continued.budgets);
    for (std::size_t i = 0; i < whole.levels.size(); ++i) {
        EXPECT_TRUE(same_mesh_bytes(whole.levels[i].trunk, continued.levels[i].trunk)) << i;
        EXPECT_TRUE(same_mesh_bytes(whole.levels[i].crown, continued.levels[i].crown)) << i;
        EXPECT_TRUE(same_mesh_bytes(whole.levels[i].leaves, continued.levels[i].leaves)) << i;
    }
}

}  // namespace
}  // namespace sylva
