// Leaves a triangle each: where a game mesh's leaf budget is about the count of its large
// leaves, every leaf keeps its place and area (a palm's fronds stay combs of leaflets, not cards
// filling the gaps between them), smaller budgets keep subsets, spare triangles keep leaves whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "quality/silhouette.h"
#include "tree/leaf_cards.h"
#include "tree/leaf_thinning.h"
#include "tree/leaf_triangles.h"
#include "tree/lowpoly_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

float triangle_area(const Mesh& m, std::size_t f) {
    const auto& t = m.triangles[f];
    return 0.5f * glm::length(glm::cross(m.positions[t[1]] - m.positions[t[0]],
                                         m.positions[t[2]] - m.positions[t[0]]));
}

glm::vec3 triangle_centroid(const Mesh& m, std::size_t f) {
    const auto& t = m.triangles[f];
    return (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0f;
}

// `n` skewed kites in a row, as a palm's leaflets: base, left, tip, right, fanned from the
// base, 0.3 apart; kite i is (1 + i / n) times `size` (about its length).
Mesh kites(int n, float size = 1.0f) {
    Mesh leaves;
    for (int i = 0; i < n; ++i) {
        const float s = size * (1.0f + static_cast<float>(i) / static_cast<float>(n));
        const glm::vec3 base(0.3f * static_cast<float>(i), 2.0f, 0.0f);
        const auto first = static_cast<std::uint32_t>(leaves.positions.size());
        leaves.positions.push_back(base);
        leaves.positions.push_back(base + s * glm::vec3(0.10f, 0.39f, 0.0f));
        leaves.positions.push_back(base + s * glm::vec3(0.10f, 0.99f, 0.0f));
        leaves.positions.push_back(base + s * glm::vec3(-0.10f, 0.39f, 0.0f));
        leaves.triangles.push_back({first, first + 1, first + 2});
        leaves.triangles.push_back({first, first + 2, first + 3});
    }
    return leaves;
}

TEST(LeafTriangles, EachKeepsItsLeafsCentroidAndAreaBaseFirst) {
    const Mesh leaves = kites(30);
    const std::vector<LeafPiece> pieces = split_leaves(leaves);
    // Fewer triangles than leaves: 20 kept, each grown by 30 / 20 in area.
    const Mesh few = leaf_triangles(leaves, 20);
    ASSERT_EQ(few.triangles.size(), 20u);
    EXPECT_EQ(count_leaves(few), 20u);
    std::vector<glm::vec3> few_centres;
    for (std::size_t f = 0; f < few.triangles.size(); ++f) {
        const glm::vec3 c = triangle_centroid(few, f);
        few_centres.push_back(c);
        // Its leaf: the kite whose centroid it has.
        bool found = false;
        for (const LeafPiece& leaf : pieces) {
            float area = 0.0f;
            glm::vec3 centroid(0.0f);
            for (std::uint32_t t : leaf.triangles) {
                area += triangle_area(leaves, t);
                centroid += triangle_area(leaves, t) * triangle_centroid(leaves, t);
            }
            centroid /= area;
            if (glm::distance(centroid, c) > 1e-4f) continue;
            found = true;
            EXPECT_NEAR(triangle_area(few, f), 1.5f * area, 1e-3f * area);
            // The first corner is the one nearest the leaf's base, the normal the leaf's.
            const glm::vec3 base = leaves.positions[leaf.base];
            const auto& t = few.triangles[f];
            for (int k = 1; k < 3; ++k)
                EXPECT_LE(glm::distance(few.positions[t[0]], base),
                          glm::distance(few.positions[t[k]], base));
            const glm::vec3 n = glm::cross(few.positions[t[1]] - few.positions[t[0]],
                                           few.positions[t[2]] - few.positions[t[0]]);
            EXPECT_GT(n.z, 0.0f);
        }
        EXPECT_TRUE(found) << "triangle " << f;
    }
    // A smaller budget keeps a subset.
    const Mesh fewer = leaf_triangles(leaves, 10);
    ASSERT_EQ(fewer.triangles.size(), 10u);
    for (std::size_t f = 0; f < fewer.triangles.size(); ++f) {
        const glm::vec3 c = triangle_centroid(fewer, f);
        EXPECT_TRUE(std::any_of(few_centres.begin(), few_centres.end(),
                                [&](const glm::vec3& p) { return glm::distance(p, c) < 1e-4f; }));
    }
    // More triangles than leaves: every leaf, the spare triangles keeping leaves whole.
    const Mesh most = leaf_triangles(leaves, 40);
    EXPECT_EQ(most.triangles.size(), 40u);
    EXPECT_EQ(count_leaves(most), 30u);
    EXPECT_EQ(leaf_triangles(leaves, 20).positions, few.positions);  // deterministic
    EXPECT_TRUE(leaf_triangles(Mesh{}, 20).triangles.empty());
    EXPECT_TRUE(leaf_triangles(leaves, 0).triangles.empty());
}

TEST(LeafTriangles, OnlyForLargeQuadLeavesAboutAsManyAsTheBudget) {
    const Mesh leaves = kites(30);
    EXPECT_FALSE(leaves_fit_as_triangles(leaves, 60));  // they fit as they are
    EXPECT_TRUE(leaves_fit_as_triangles(leaves, 59));
    EXPECT_TRUE(leaves_fit_as_triangles(leaves, 20));
    EXPECT_FALSE(leaves_fit_as_triangles(leaves, 19));  // more than 1.5 leaves a triangle
    // A leaf of five corners loses too much of its outline in one triangle.
    Mesh round = leaves;
    round.positions.push_back(round.positions[2] + glm::vec3(0.0f, 0.1f, 0.0f));
    round.triangles.push_back({0, 2, static_cast<std::uint32_t>(round.positions.size() - 1)});
    EXPECT_FALSE(leaves_fit_as_triangles(round, 40));
    // Small leaves (a twentieth of the row's length) read as foliage: cards draw them.
    EXPECT_FALSE(leaves_fit_as_triangles(kites(30, 0.3f), 40));
}

// The palm at 200 + 200 leaf triangles: its 212 leaflets a triangle each keep the fronds'
// outline far better than cards for two or three leaflets each, which fill the gaps.
TEST(LeafTriangles, APalmsFrondsKeepTheirOutlineAtASmallBudget) {
    MeshOptions options;
    options.budget = 200;
    const Tree tree = generate_tree(load_template("palm"), options);
    TreeBudget budget;
    budget.total = 200;
    const ReducedTree reduced = reduce_tree(tree, budget);
    EXPECT_LE(reduced.leaves.triangles.size(), 200u);
    EXPECT_EQ(count_leaves(reduced.leaves), reduced.leaves.triangles.size());
    EXPECT_GE(count_leaves(reduced.leaves), 190u);

    const Mesh cards = leaf_cards(tree.leaves, {.max_triangles = 200});
    const Mesh* reference[] = {&tree.leaves};
    const Mesh* triangles[] = {&reduced.leaves};
    const Mesh* carded[] = {&cards};
    const double with_triangles = silhouette_iou(reference, triangles).mean;
    const double with_cards = silhouette_iou(reference, carded).mean;
    EXPECT_GT(with_triangles, 0.7);
    EXPECT_GT(with_triangles, with_cards + 0.1);
}

}  // namespace
}  // namespace sylva
