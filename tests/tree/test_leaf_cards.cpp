// Leaf cards: within their budget and using it, on the crown's surface and facing out of it,
// laid out as leaves so their UVs fill the unit square, deterministic; and the other leaf
// styles: none draws no leaves, leaves keeps some of the tree's own.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <string>

#include "core/mesh_checks.h"
#include "export/part_attributes.h"
#include "lowpoly/triangle_bvh.h"
#include "tree/leaf_cards.h"
#include "tree/leaf_thinning.h"
#include "tree/lowpoly_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

Tree game_tree(const std::string& name, std::size_t budget, LeafStyle style = LeafStyle::Cards) {
    TreeTemplate t = load_template(name);
    t.params.leaf_style = style;
    MeshOptions options;
    options.budget = budget;
    return generate_tree(t, options);
}

glm::vec3 card_normal(const Mesh& cards, std::size_t card) {
    const auto& t = cards.triangles[2 * card];
    return glm::normalize(glm::cross(cards.positions[t[1]] - cards.positions[t[0]],
                                     cards.positions[t[2]] - cards.positions[t[0]]));
}

glm::vec3 card_centre(const Mesh& cards, std::size_t card) {
    return 0.25f * (cards.positions[4 * card] + cards.positions[4 * card + 1] +
                    cards.positions[4 * card + 2] + cards.positions[4 * card + 3]);
}

TEST(LeafCards, FillTheirBudgetAndNeverPassIt) {
    for (const char* name : {"oak", "spruce", "bush", "honda"}) {
        const Tree tree = game_tree(name, 800);
        for (std::size_t budget : {50, 200, 800}) {
            if (count_leaves(tree.leaves) * 2 <= budget) continue;  // a card per leaf
            const Mesh cards = leaf_cards(tree.leaves, {.max_triangles = budget});
            EXPECT_LE(cards.triangles.size(), budget) << name << " at " << budget;
            // The grid grows by a fifth at a time: it never ends below half the cards allowed.
            EXPECT_GE(cards.triangles.size(), budget / 2) << name << " at " << budget;
            EXPECT_EQ(count_leaves(cards), cards.triangles.size() / 2);  // diamonds apart
            // A smaller budget gives fewer, larger cards.
            if (budget > 50) {
                const Mesh fewer = leaf_cards(tree.leaves, {.max_triangles = budget / 4});
                auto mean_area = [](const Mesh& m) {
                    double area = 0.0;
                    for (const auto& t : m.triangles)
                        area +=
                            0.5 * glm::length(glm::cross(m.positions[t[1]] - m.positions[t[0]],
                                                         m.positions[t[2]] - m.positions[t[0]]));
                    return area / static_cast<double>(m.triangles.size());
                };
                EXPECT_GT(mean_area(fewer), 1.5 * mean_area(cards)) << name << " at " << budget;
            }
        }
        const Mesh once = leaf_cards(tree.leaves, {.max_triangles = 200});
        const Mesh again = leaf_cards(tree.leaves, {.max_triangles = 200});
        EXPECT_EQ(once.positions, again.positions) << name;
    }
    EXPECT_TRUE(leaf_cards(Mesh{}, {}).triangles.empty());
    // Few leaves: a card each.
    const Tree baobab = game_tree("baobab", 800);
    EXPECT_EQ(leaf_cards(baobab.leaves, {.max_triangles = 800}).triangles.size(),
              2 * count_leaves(baobab.leaves));
}

// On a crowned tree the cards lie in the crown's leaf shell and face out of the crown: away
// from its middle (the crown's own surface is too bumpy to say more: a spruce's is hundreds of
// small balls).
TEST(LeafCards, LieOnTheCrownAndFaceOut) {
    for (const char* name : {"oak", "maple", "spruce", "cypress"}) {
        const Tree tree = game_tree(name, 800);
        ASSERT_FALSE(tree.crown.triangles.empty()) << name;
        const TriangleBvh crown(tree.crown);
        const Mesh cards = leaf_cards(tree.leaves, {.max_triangles = 400});
        const std::size_t n = cards.triangles.size() / 2;
        glm::vec3 lo(1e9f), hi(-1e9f);
        for (const glm::vec3& p : tree.crown.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const glm::vec3 middle = 0.5f * (lo + hi);
        // The leaves fill a shell a leaf deep under the crown's surface.
        const float reach = 0.1f * glm::length(hi - lo);
        std::size_t near = 0, out = 0;
        for (std::size_t c = 0; c < n; ++c) {
            const glm::vec3 centre = card_centre(cards, c);
            near += crown.distance(centre) < reach;
            out += glm::dot(card_normal(cards, c), centre - middle) > 0.0f;
        }
        EXPECT_GE(near, n * 95 / 100) << name;
        EXPECT_GE(out, n * 90 / 100) << name;
    }
}

// A flat frond: leaflets all lying level in a row along x. Facing out of the crown (here
// sideways) its cards would show their edges from above and their faces from the side; the
// leaflets lie alike, so each card lies as they do and runs along them.
TEST(LeafCards, ACardOfLeavesThatLieAlikeLiesAsTheyDo) {
    Mesh leaves;
    for (int i = 0; i < 80; ++i) {
        const float x = 1.0f + 0.05f * static_cast<float>(i);
        const float z = 0.1f * static_cast<float>((i * 7) % 5 - 2);
        const glm::vec3 base(x, 1.0f, z);
        const auto first = static_cast<std::uint32_t>(leaves.positions.size());
        leaves.positions.push_back(base);
        leaves.positions.push_back(base + glm::vec3(0.1f, 0.0f, -0.03f));
        leaves.positions.push_back(base + glm::vec3(0.2f, 0.0f, 0.0f));
        leaves.positions.push_back(base + glm::vec3(0.1f, 0.0f, 0.03f));
        leaves.triangles.push_back({first, first + 1, first + 2});
        leaves.triangles.push_back({first, first + 2, first + 3});
    }
    const Mesh cards = leaf_cards(leaves, {.max_triangles = 20});
    ASSERT_GT(cards.triangles.size(), 0u);
    ASSERT_LE(cards.triangles.size(), 20u);
    for (std::size_t c = 0; c < cards.triangles.size() / 2; ++c) {
        EXPECT_GT(std::abs(card_normal(cards, c).y), 0.99f) << "card " << c;
        // Base to tip (the card's first and third corners) along the leaflets.
        const glm::vec3 along = glm::normalize(cards.positions[4 * c + 2] - cards.positions[4 * c]);
        EXPECT_GT(along.x, 0.99f) << "card " << c;
    }
}

// Small leaves spread apart (a shrub's twigs): a card for several of them would span the sky
// between them. In the open the cards' area stays within 1.75 times the leaves'; over a crown
// they keep the leaves' spread (their overlap lies on the crown).
TEST(LeafCards, ACardInTheOpenIsNoLargerThanItsLeavesNeed) {
    Mesh leaves;
    for (int i = 0; i < 64; ++i) {
        const glm::vec3 base(0.5f * static_cast<float>(i % 4), 0.5f * static_cast<float>(i / 16),
                             0.5f * static_cast<float>((i / 4) % 4));
        const auto first = static_cast<std::uint32_t>(leaves.positions.size());
        leaves.positions.push_back(base);
        leaves.positions.push_back(base + glm::vec3(0.05f, 0.05f, 0.0f));
        leaves.positions.push_back(base + glm::vec3(0.0f, 0.1f, 0.0f));
        leaves.positions.push_back(base + glm::vec3(-0.05f, 0.05f, 0.0f));
        leaves.triangles.push_back({first, first + 1, first + 2});
        leaves.triangles.push_back({first, first + 2, first + 3});
    }
    const Mesh open = leaf_cards(leaves, {.max_triangles = 16});
    ASSERT_GT(open.triangles.size(), 0u);
    EXPECT_LE(surface_area(open), 1.75 * surface_area(leaves) * 1.001);
    Mesh crown;  // a crown surface through every leaf
    crown.positions = leaves.positions;
    const Mesh over_crown = leaf_cards(leaves, {.max_triangles = 16, .crown = &crown});
    EXPECT_GT(surface_area(over_crown), 4.0 * surface_area(leaves));
}

TEST(LeafCards, TheirUvsFillTheUnitSquareAsALeafs) {
    const Tree tree = game_tree("oak", 800);
    const Mesh cards = leaf_cards(tree.leaves, {.max_triangles = 200});
    const PartAttributes a =
        leaf_attributes(cards, tree_frame(tree.trunk, tree.crown, cards), EngineSettings{});
    ASSERT_EQ(a.uv.size(), cards.triangles.size());
    glm::vec2 lo(1.0f), hi(0.0f);
    for (const auto& corners : a.uv)
        for (const glm::vec2& uv : corners) {
            EXPECT_GE(uv.x, 0.0f);
            EXPECT_LE(uv.x, 1.0f);
            EXPECT_GE(uv.y, 0.0f);
            EXPECT_LE(uv.y, 1.0f);
            lo = glm::min(lo, uv), hi = glm::max(hi, uv);
        }
    // v runs from the base (0) to the tip (1); u across, both edges reached.
    EXPECT_NEAR(lo.y, 0.0f, 1e-4f);
    EXPECT_NEAR(hi.y, 1.0f, 1e-4f);
    EXPECT_LT(lo.x, 0.2f);
    EXPECT_GT(hi.x, 0.8f);
}

TEST(LeafStyles, NoneDrawsNoLeavesAndLeavesKeepsTheTreesOwn) {
    TreeBudget budget;
    budget.total = 200;
    const Tree none = game_tree("oak", 200, LeafStyle::None);
    EXPECT_TRUE(none.leaves.triangles.empty());
    EXPECT_TRUE(reduce_tree(none, budget).leaves.triangles.empty());

    const Tree own = game_tree("oak", 200, LeafStyle::Leaves);
    const ReducedTree kept = reduce_tree(own, budget);
    EXPECT_LE(kept.leaves.triangles.size(), 200u);
    EXPECT_GT(kept.leaves.triangles.size(), 0u);
    EXPECT_EQ(kept.leaves.positions, thin_leaves(own.leaves, 200).positions);

    const Tree cards = game_tree("oak", 200);
    const ReducedTree carded = reduce_tree(cards, budget);
    EXPECT_EQ(count_leaves(carded.leaves), carded.leaves.triangles.size() / 2);
    EXPECT_GT(count_leaves(carded.leaves), count_leaves(kept.leaves));
}

}  // namespace
}  // namespace sylva
