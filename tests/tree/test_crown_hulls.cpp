// Low budgets draw the crown as a few convex hulls (tree/crown_hulls.h), and neither part of
// a low-budget tree shrinks to a token (tree/lowpoly_tree.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/disjoint_sets.h"
#include "core/mesh_checks.h"
#include "tree/crown_hulls.h"
#include "tree/crown_merge.h"
#include "tree/lowpoly_tree.h"
#include "tree/parameters.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

// An axis-aligned box as a closed mesh, counter-clockwise from outside.
Mesh box(glm::vec3 lo, glm::vec3 hi) {
    Mesh m;
    for (int i = 0; i < 8; ++i)
        m.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

Mesh two_boxes() {
    Mesh a = box({0, 0, 0}, {1, 1, 1});
    const Mesh b = box({5, 0, 0}, {6, 1, 1});
    for (const auto& t : b.triangles) a.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    return a;
}

void expect_closed_outward(const Mesh& part, const std::string& what) {
    ASSERT_FALSE(part.triangles.empty()) << what;
    const MeshTopology topology = check_topology(part);
    EXPECT_TRUE(topology.is_closed_manifold()) << what << ": " << to_string(topology);
    for (double volume : component_volumes(part))
        EXPECT_GT(volume, 0.0) << what << ": a piece is inside out or has no volume";
}

void bounds(const Mesh& m, glm::vec3& lo, glm::vec3& hi) {
    lo = glm::vec3(1e30f);
    hi = glm::vec3(-1e30f);
    for (const glm::vec3& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
}

TEST(CrownHulls, TwoSeparateBlobsBecomeTwoHullsCoveringThem) {
    const Mesh hulls = crown_hulls(two_boxes(), 2, 2);
    expect_closed_outward(hulls, "hulls");
    const auto volumes = component_volumes(hulls);
    ASSERT_EQ(volumes.size(), 2u);
    // The hull of a box is the box: nothing lost, nothing added.
    for (double v : volumes) EXPECT_NEAR(v, 1.0, 1e-4);
}

// One cluster over two blobs apart is split into a hull per blob where the pieces allow it;
// held to one piece, its hull bridges the gap.
TEST(CrownHulls, AClusterOverPiecesApartIsSplitUpToThePieces) {
    const auto split = component_volumes(crown_hulls(two_boxes(), 1, 2));
    ASSERT_EQ(split.size(), 2u);
    for (double v : split) EXPECT_NEAR(v, 1.0, 1e-4);
    const auto bridged = component_volumes(crown_hulls(two_boxes(), 1, 1));
    ASSERT_EQ(bridged.size(), 1u);
    EXPECT_GT(bridged[0], 2.0 + 1e-3);
}

// Two flat tiers, one above the other, each a layer of small blobs (no piece large enough to
// split a cluster by itself): the hulls each keep to one tier, none reaches across the sky
// between them, though k-means on the plain positions makes columns through both.
TEST(CrownHulls, HullsOverFlatTiersKeepToATier) {
    constexpr float kRise = 1.1f;  // from one tier to the next
    Mesh crown;
    for (int tier = 0; tier < 2; ++tier)
        for (int i = 0; i < 8; ++i)
            for (int j = 0; j < 8; ++j) {
                const glm::vec3 lo(0.5f * static_cast<float>(i), kRise * static_cast<float>(tier),
                                   0.5f * static_cast<float>(j));
                const Mesh blob = box(lo, lo + glm::vec3(0.4f, 0.1f, 0.4f));
                const auto first = static_cast<std::uint32_t>(crown.positions.size());
                crown.positions.insert(crown.positions.end(), blob.positions.begin(),
                                       blob.positions.end());
                for (const auto& t : blob.triangles)
                    crown.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
            }
    const Mesh hulls = crown_hulls(crown, 8, 8);
    expect_closed_outward(hulls, "hulls");
    DisjointSets pieces(static_cast<std::uint32_t>(hulls.positions.size()));
    for (const auto& t : hulls.triangles) {
        pieces.unite(t[0], t[1]);
        pieces.unite(t[1], t[2]);
    }
    std::vector<float> low(hulls.positions.size(), 1e30f), high(hulls.positions.size(), -1e30f);
    for (std::uint32_t v = 0; v < hulls.positions.size(); ++v) {
        const std::uint32_t root = pieces.find(v);
        low[root] = std::min(low[root], hulls.positions[v].y);
        high[root] = std::max(high[root], hulls.positions[v].y);
    }
    for (std::uint32_t v = 0; v < hulls.positions.size(); ++v) {
        if (pieces.find(v) != v) continue;
        EXPECT_LT(high[v] - low[v], 0.5f) << "a hull spans both tiers";
    }
}

TEST(CrownHulls, ZeroHullsOrAFlatCrownKeepsTheCrown) {
    const Mesh crown = two_boxes();
    EXPECT_EQ(crown_hulls(crown, 0, 0).triangles, crown.triangles);
    Mesh flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    flat.triangles = {{0, 1, 2}};
    EXPECT_EQ(crown_hulls(flat, 3, 3).triangles, flat.triangles);
}

TEST(CrownHulls, HullsAreTheDefaultOfGameMeshesAndAnOption) {
    TreeBudget b;
    b.total = 200;
    EXPECT_EQ(crown_hull_count(b), 200u / kTrianglesPerHull);
    b.total = 3000;
    EXPECT_EQ(crown_hull_count(b), 3000u / kTrianglesPerHull);
    b.crown_shape = CrownShape::Hulls;
    EXPECT_GT(crown_hull_count(b), 0u);
    b.total = 100;
    b.crown_shape = CrownShape::Blobs;
    EXPECT_EQ(crown_hull_count(b), 0u);
    b.total = 0;  // no reduction: the crown as meshed
    b.crown_shape = CrownShape::Automatic;
    EXPECT_EQ(crown_hull_count(b), 0u);
}

// The many-blob crowns (ternary: hundreds of tip spheres; willow: a hanging curtain; maple:
// a dense round mass over a trunk in pieces; all with handles where blobs touch in rings) at
// a budget where reducing the blobs alone would leave a spray of shards: a few closed outward
// hulls within the tree's box, and a trunk and a crown that each keep a real share of the
// budget.
TEST(CrownHulls, ALowBudgetCrownIsAFewClosedPiecesAndNeitherPartIsStarved) {
    for (const std::string name : {"ternary", "willow", "maple"}) {
        SCOPED_TRACE(name);
        TreeBudget budget;
        budget.total = 200;
        MeshOptions options;
        options.budget = budget.total;
        const Tree tree = generate_tree(load_template(name), options);
        ASSERT_FALSE(tree.crown.triangles.empty());
        budget.lump_triangles = tree.crown_lump_triangles;  // the template's lumps
        const ReducedTree reduced = reduce_tree(tree, budget);
        expect_closed_outward(reduced.trunk, "trunk");
        expect_closed_outward(reduced.crown, "crown");
        // The hulls, or half as many again when those keep closer to the crown.
        EXPECT_LE(component_volumes(reduced.crown).size(), crown_hull_count(budget) * 3 / 2);
        glm::vec3 lo, hi, trunk_lo, trunk_hi, crown_lo, crown_hi;
        bounds(tree.crown, lo, hi);
        bounds(tree.trunk, trunk_lo, trunk_hi);
        lo = glm::min(lo, trunk_lo);
        hi = glm::max(hi, trunk_hi);
        bounds(reduced.crown, crown_lo, crown_hi);
        // The hulls lie within the tree's box; the reduction's quadric-optimal placement
        // moves a hull's corners out to where its tangent planes meet (a few percent of the
        // height), not more. Without that placement the hulls stay inside but lose more of
        // the crown (a worse Hausdorff distance).
        const glm::vec3 size = hi - lo;
        const float slack = 0.05f * std::max({size.x, size.y, size.z});
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(crown_lo[axis], lo[axis] - slack) << "axis " << axis;
            EXPECT_LE(crown_hi[axis], hi[axis] + slack) << "axis " << axis;
        }
        EXPECT_LE(reduced.triangles, budget.total);
        // A share each: the crown at least a quarter of the budget; the branches, drawn as
        // prisms, as many as their share (at least a quarter) buys, whole branches at a time.
        EXPECT_GE(reduced.trunk.triangles.size(), budget.total / 5);
        EXPECT_GE(reduced.crown.triangles.size(), budget.total / 4);
        // Blobs on request: the crown reduced as meshed, closed and outward as well, and
        // not what the automatic mode drew (these crowns have handles: hulls).
        budget.crown_shape = CrownShape::Blobs;
        const ReducedTree blobs = reduce_tree(tree, budget);
        expect_closed_outward(blobs.crown, "blob crown");
        EXPECT_NE(blobs.crown.positions, reduced.crown.positions);
    }
}

// A tree whose branches are prisms counts its lumps on the whole budget, as a tree without
// them does, not on what the prisms leave the crown: a willow at 800 (from 400 on only the
// hulls are drawn) has a lump per 25 triangles of the 800, more than its crown's rest buys.
TEST(CrownHulls, APrismTreeCountsItsLumpsOnTheWholeBudget) {
    TreeBudget budget;
    budget.total = 800;
    budget.leaves = 0;
    MeshOptions options;
    options.budget = budget.total;
    const Tree tree = generate_tree(load_template("willow"), options);
    ASSERT_FALSE(tree.branch_axes.axes.empty());
    budget.lump_triangles = tree.crown_lump_triangles;
    const ReducedTree reduced = reduce_tree(tree, budget);
    const std::size_t pieces = component_volumes(reduced.crown).size();
    TreeBudget rest = budget;
    rest.total = budget.total - reduced.trunk.triangles.size();
    EXPECT_GT(pieces, crown_hull_count(rest) * 3 / 2);  // more than the rest's most
    EXPECT_GE(pieces, crown_hull_count(budget));
    EXPECT_LE(pieces, crown_hull_count(budget) * 3 / 2);
    EXPECT_LE(reduced.triangles, budget.total);
}

// The automatic choice for a crown of sphere-like pieces (pine: a cone of blobs, no tunnel):
// its own surface, as CrownShape::Blobs gives it. (Crowns with handles, above, get hulls.)
TEST(CrownHulls, ACrownWithoutHandlesKeepsItsOwnSurface) {
    TreeBudget budget;
    budget.total = 200;
    MeshOptions options;
    options.budget = budget.total;
    const Tree tree = generate_tree(load_template("pine"), options);
    const ReducedTree automatic = reduce_tree(tree, budget);
    budget.crown_shape = CrownShape::Blobs;
    EXPECT_EQ(automatic.crown.positions, reduce_tree(tree, budget).crown.positions);
}

// The template's crown_shape draws the game mesh's crown (the studio's and every export's
// choice) unless the budget itself says: a pine asking for hulls at 800 (where the automatic
// mode keeps the blobs) gets what an explicit Hulls budget gives, and an explicit Blobs
// budget overrides the template.
TEST(CrownHulls, TheTemplatesCrownShapeUnlessTheBudgetSays) {
    TreeTemplate pine = load_template("pine");
    MeshOptions options;
    options.budget = 800;
    const Tree automatic = generate_tree(pine, options);
    EXPECT_EQ(automatic.crown_shape, CrownShape::Automatic);
    set_param(pine.params, "crown_shape", "hulls");
    const Tree hulls = generate_tree(pine, options);
    EXPECT_EQ(hulls.crown_shape, CrownShape::Hulls);
    TreeBudget budget;
    budget.total = 800;
    const ReducedTree by_template = reduce_tree(hulls, budget);
    const ReducedTree blobs = reduce_tree(automatic, budget);
    EXPECT_NE(by_template.crown.positions, blobs.crown.positions);
    budget.crown_shape = CrownShape::Hulls;
    EXPECT_EQ(by_template.crown.positions, reduce_tree(automatic, budget).crown.positions);
    budget.crown_shape = CrownShape::Blobs;
    EXPECT_EQ(blobs.crown.positions, reduce_tree(hulls, budget).crown.positions);
    // The LOD chain too: every level's crown from the template's hulls.
    budget.crown_shape = std::nullopt;
    const std::vector<TreeBudget> budgets = lod_budgets(budget, 2);
    EXPECT_EQ(make_lod_chain(hulls, budgets).front().crown.positions, by_template.crown.positions);
}

// A LOD chain through the hull budgets: every level within its budget (a level's hulls are
// made from the finest crown, as many as its budget buys, not from the level before, whose
// pieces a smaller budget could not draw), per-part counts never rising, every part sound.
TEST(CrownHulls, ALowBudgetLodChainMeetsEveryLevelsBudget) {
    TreeBudget finest;
    finest.total = 300;
    finest.leaves = 0;
    MeshOptions options;
    options.budget = finest.total;
    const Tree tree = generate_tree(load_template("honda"), options);
    const std::vector<TreeBudget> budgets = lod_budgets(finest, 4);
    const std::vector<ReducedTree> levels = make_lod_chain(tree, budgets);
    ASSERT_EQ(levels.size(), budgets.size());
    for (std::size_t i = 0; i < levels.size(); ++i) {
        SCOPED_TRACE("LOD" + std::to_string(i));
        EXPECT_LE(levels[i].triangles, budgets[i].total);
        expect_closed_outward(levels[i].trunk, "trunk");
        expect_closed_outward(levels[i].crown, "crown");
        if (i == 0) continue;
        EXPECT_LE(levels[i].trunk.triangles.size(), levels[i - 1].trunk.triangles.size());
        EXPECT_LE(levels[i].crown.triangles.size(), levels[i - 1].crown.triangles.size());
    }
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

// A reference for crown_bridges, without Kruskal's search: the growth bisected with
// count_crown_pieces to 1% of the crown's size, then Kruskal's order over the pairs closer
// than twice that growth (all pairs tried here, not a grid).
std::vector<std::pair<std::uint32_t, std::uint32_t>> bisected_bridges(std::span<const Ball> balls,
                                                                      std::size_t max_pieces) {
    if (count_crown_pieces(balls, 0.0f) <= std::max<std::size_t>(max_pieces, 1)) return {};
    glm::vec3 lo(balls[0].center), hi(balls[0].center);
    for (const Ball& b : balls) {
        lo = glm::min(lo, b.center);
        hi = glm::max(hi, b.center);
    }
    float low = 0.0f, high = 0.5f * glm::distance(lo, hi) + 1e-3f;
    const float precision = 0.01f * high;
    while (high - low > precision) {
        const float mid = 0.5f * (low + high);
        (count_crown_pieces(balls, mid) <= max_pieces ? high : low) = mid;
    }
    std::vector<std::tuple<float, std::uint32_t, std::uint32_t>> gaps;
    for (std::uint32_t i = 0; i < balls.size(); ++i)
        for (std::uint32_t j = i + 1; j < balls.size(); ++j) {
            const float gap =
                glm::distance(balls[i].center, balls[j].center) - balls[i].radius - balls[j].radius;
            if (gap < 2.0f * high) gaps.emplace_back(gap, i, j);
        }
    std::sort(gaps.begin(), gaps.end());
    std::vector<std::uint32_t> parent(balls.size());
    for (std::uint32_t i = 0; i < balls.size(); ++i) parent[i] = i;
    const auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x];
        return x;
    };
    std::size_t pieces = balls.size();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> bridges;
    for (const auto& [gap, i, j] : gaps) {
        if (pieces <= max_pieces && gap > 0.0f) break;
        const std::uint32_t a = find(i), b = find(j);
        if (a == b) continue;
        parent[a] = b;
        --pieces;
        if (gap > 0.0f) bridges.emplace_back(i, j);
    }
    return bridges;
}

// Clusters of spheres, some overlapping, some touching, some alone, far apart or close.
std::vector<Ball> random_crown(std::mt19937& random) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const int clusters = 1 + int(random() % 12);
    const float spread = 0.5f + 20.0f * unit(random);
    std::vector<Ball> balls;
    for (int c = 0; c < clusters; ++c) {
        const glm::vec3 centre(spread * unit(random), spread * unit(random), spread * unit(random));
        const int count = 1 + int(random() % 24);
        const float size = 0.05f + unit(random);
        for (int k = 0; k < count; ++k) {
            const glm::vec3 offset(unit(random) - 0.5f, unit(random) - 0.5f, unit(random) - 0.5f);
            balls.push_back({centre + 3.0f * size * offset, size * (0.2f + unit(random))});
            if (random() % 8 == 0)  // a twin touching it: a gap of (about) zero
                balls.push_back({balls.back().center + glm::vec3(2.0f * balls.back().radius, 0, 0),
                                 balls.back().radius});
        }
    }
    return balls;
}

TEST(CrownMerge, BridgesAreThoseOfTheBisectedGrowth) {
    std::mt19937 random(11);
    for (int round = 0; round < 60; ++round) {
        const std::vector<Ball> balls = random_crown(random);
        for (const std::size_t max_pieces : {0u, 1u, 2u, 4u, 7u, 16u}) {
            SCOPED_TRACE("round " + std::to_string(round) + ", " + std::to_string(balls.size()) +
                         " balls, at most " + std::to_string(max_pieces) + " pieces");
            const auto bridges = crown_bridges(balls, max_pieces);
            EXPECT_EQ(bridges, bisected_bridges(balls, max_pieces));
            // The spheres (touching at a gap of 0 or less) and the bridges form at most
            // max(max_pieces, 1) pieces.
            DisjointSets sets(balls.size());
            std::size_t pieces = balls.size();
            for (std::uint32_t i = 0; i < balls.size(); ++i)
                for (std::uint32_t j = i + 1; j < balls.size(); ++j)
                    if (glm::distance(balls[i].center, balls[j].center) - balls[i].radius -
                                balls[j].radius <=
                            0.0f &&
                        sets.unite(i, j))
                        --pieces;
            for (const auto& [i, j] : bridges) pieces -= sets.unite(i, j) ? 1 : 0;
            EXPECT_LE(pieces, std::max<std::size_t>(max_pieces, 1));
        }
    }
}

// The seed spruce at 800: its small balls, every one kept, each reduced to a few triangles, grown
// back to the area of the balls the crown was meshed from (without, an inscribed polyhedron keeps
// little more than half of it), each still closed and outward.
TEST(CrownBlobs, BallsReducedToAFewTrianglesKeepTheirArea) {
    TreeBudget budget;
    budget.total = 800;
    MeshOptions options;
    options.budget = budget.total;
    const Tree tree = generate_tree(load_template("seed_spruce"), options);
    ASSERT_EQ(tree.crown_bridges, 0u);
    const ReducedTree reduced = reduce_tree(tree, budget);
    const std::size_t pieces = component_volumes(reduced.crown).size();
    ASSERT_GE(pieces, 30u);
    EXPECT_EQ(pieces, component_volumes(tree.crown).size()) << "every ball kept";
    ASSERT_LE(reduced.crown.triangles.size(), 10 * pieces);  // a few triangles a ball
    expect_closed_outward(reduced.crown, "crown");
    EXPECT_GE(surface_area(reduced.crown), 0.95 * surface_area(tree.crown));
}

TEST(CrownMerge, EmptyAndSingleCrownsNeedNoBridges) {
    EXPECT_TRUE(crown_bridges({}, 1).empty());
    const std::vector<Ball> one = {{{0, 0, 0}, 1.0f}};
    EXPECT_TRUE(crown_bridges(one, 0).empty());
}

}  // namespace
}  // namespace sylva
