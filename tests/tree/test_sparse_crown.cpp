// A sparse crown (tree/sparse_crown.h): blobs far apart for their size are told from blobs
// that crowd, and drawn as one regular polyhedron each with the blob's mean outline, the
// largest kept where the budget cannot draw them all; on the seed spruce, whose tufts sit at
// the tips of bare whorls, that keeps its silhouette where bridged slabs covered the gaps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "../quality/shapes.h"
#include "core/mesh_checks.h"
#include "lowpoly/merge_meshes.h"
#include "quality/self_intersections.h"
#include "quality/silhouette.h"
#include "tree/lowpoly_tree.h"
#include "tree/pipeline.h"
#include "tree/sparse_crown.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

// `count` balls on the x axis, `spacing` apart, of radius `radius` + `growth` i (the i-th).
Mesh balls_in_a_row(int count, float radius, float spacing, float growth = 0.0f) {
    Mesh row;
    for (int i = 0; i < count; ++i) {
        Mesh ball = test::icosphere(2);
        const float r = radius + growth * static_cast<float>(i);
        for (glm::vec3& p : ball.positions)
            p = r * p + glm::vec3(spacing * static_cast<float>(i), 0.0f, 0.0f);
        test::append(row, ball);
    }
    return row;
}

TEST(SparseCrown, BlobsFarApartForTheirSizeAreSparse) {
    EXPECT_EQ(sparse_crown_pieces(balls_in_a_row(10, 0.1f, 1.0f)), 10u);  // ten radii apart
    EXPECT_EQ(sparse_crown_pieces(balls_in_a_row(10, 0.1f, 0.3f)), 0u);   // three radii apart
    EXPECT_EQ(sparse_crown_pieces(balls_in_a_row(1, 0.1f, 1.0f)), 0u);    // one piece
    EXPECT_EQ(sparse_crown_pieces(Mesh{}), 0u);
}

// Every piece a polyhedron of as many triangles as the budget gives each (8, 6 or 4), with
// the area of the ball it stands for (so, by Cauchy's formula, its mean outline), closed,
// outward and not crossing itself; a budget under four a piece keeps the largest.
TEST(SparseCrown, EachBlobIsAPolyhedronWithItsBallsOutline) {
    const Mesh crown = balls_in_a_row(10, 0.1f, 1.0f, 0.005f);
    for (const auto& [budget, each] : {std::pair{80, 8}, {79, 6}, {60, 6}, {59, 4}, {40, 4}}) {
        const Mesh drawn = sparse_crown_polyhedra(crown, static_cast<std::size_t>(budget));
        const std::string what = "budget " + std::to_string(budget);
        EXPECT_EQ(drawn.triangles.size(), 10u * static_cast<std::size_t>(each)) << what;
        const MeshTopology topology = check_topology(drawn);
        EXPECT_TRUE(topology.is_closed_manifold()) << what << ": " << to_string(topology);
        const std::vector<double> volumes = component_volumes(drawn);
        ASSERT_EQ(volumes.size(), 10u) << what;
        for (double volume : volumes) EXPECT_GT(volume, 0.0) << what;
        EXPECT_TRUE(find_self_intersections(drawn).pairs.empty()) << what;
        // Piece by piece (they come in the crown's order), the area of its ball.
        std::size_t count = 0;
        const std::vector<std::uint32_t> label = component_of_triangles(drawn, count);
        const std::vector<Mesh> pieces = split_by_label(drawn, label, count);
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            // An icosphere's vertices lie on its ball: their mean distance is the radius.
            const double r = 0.1 + 0.005 * static_cast<double>(i);
            EXPECT_NEAR(surface_area(pieces[i]), 4.0 * std::numbers::pi * r * r, 1e-4) << what;
        }
    }
    // Room for five tetrahedra: the five largest balls (the last five).
    const Mesh five = sparse_crown_polyhedra(crown, 20);
    ASSERT_EQ(five.triangles.size(), 20u);
    for (const glm::vec3& p : five.positions) EXPECT_GT(p.x, 4.5f);
    EXPECT_TRUE(sparse_crown_polyhedra(crown, 3).triangles.empty());
}

// The seed spruce's silhouette against its full-detail tree: its tufts stay apart (bridged
// into a few slabs they would cover the gaps between the whorls) and its branches are drawn,
// nine in ten at 200, every one at 800.
TEST(SparseCrown, TheSeedSpruceKeepsItsSilhouette) {
    const TreeTemplate spruce = load_template("seed_spruce");
    const Tree full = generate_tree(spruce);
    const Mesh* full_parts[] = {&full.trunk, &full.crown, &full.leaves};
    const SilhouetteFrame frame = silhouette_frame(full_parts);
    const Silhouettes reference = rasterize_silhouettes(full_parts, frame);
    for (const auto& [budget, least_iou] : {std::pair{200, 0.5}, {800, 0.84}}) {
        MeshOptions options;
        options.budget = static_cast<std::size_t>(budget);
        const Tree tree = generate_tree(spruce, options);
        EXPECT_EQ(tree.crown_bridges, 0u) << budget;
        TreeBudget b;
        b.total = static_cast<std::size_t>(budget);
        const ReducedTree game = reduce_tree(tree, b);
        EXPECT_LE(game.triangles, b.total);
        const std::size_t axes = tree.branch_axes.axes.size();
        EXPECT_GE(component_volumes(game.trunk).size(), budget < 800 ? axes * 9 / 10 : axes)
            << "branches drawn at " << budget;
        EXPECT_GT(component_volumes(game.crown).size(), 8u) << "tufts apart at " << budget;
        const Mesh* parts[] = {&game.trunk, &game.crown, &game.leaves};
        EXPECT_GE(silhouette_iou(reference, rasterize_silhouettes(parts, frame)).mean, least_iou)
            << budget;
    }
}

}  // namespace
}  // namespace sylva
