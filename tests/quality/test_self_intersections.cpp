#include <gtest/gtest.h>

#include "quality/self_intersections.h"
#include "shapes.h"

namespace sylva {
namespace {

using test::append;
using test::box;
using test::icosphere;

TEST(SelfIntersections, ClosedConvexMeshesHaveNone) {
    EXPECT_EQ(self_intersecting_pairs(box({0, 0, 0}, {1, 1, 1})), 0u);
    const SelfIntersections sphere = find_self_intersections(icosphere(3));
    EXPECT_EQ(sphere.pairs.size(), 0u);
    EXPECT_EQ(sphere.pieces, 1u);
    EXPECT_EQ(sphere.soup_pieces, 0u);  // a 2-manifold: CGAL's self_intersections ran
}

TEST(SelfIntersections, WeldsVerticesAtOnePosition) {
    // Every triangle with corners of its own: one piece once welded, still a 2-manifold.
    const Mesh welded = box({0, 0, 0}, {1, 1, 1});
    Mesh loose;
    for (const auto& t : welded.triangles) {
        const auto base = static_cast<std::uint32_t>(loose.positions.size());
        for (std::uint32_t v : t) loose.positions.push_back(welded.positions[v]);
        loose.triangles.push_back({base, base + 1, base + 2});
    }
    const SelfIntersections found = find_self_intersections(loose);
    EXPECT_EQ(found.pieces, 1u);
    EXPECT_EQ(found.soup_pieces, 0u);
    EXPECT_EQ(found.pairs.size(), 0u);
}

TEST(SelfIntersections, FindsAVertexPushedThroughTheFarSide) {
    // One vertex of a sphere moved through the centre to beyond the opposite side: its fan
    // of triangles pierces the far faces. Still a closed 2-manifold, one piece.
    Mesh folded = icosphere(1);
    folded.positions[0] *= -2.0f;
    const SelfIntersections found = find_self_intersections(folded);
    EXPECT_EQ(found.pieces, 1u);
    EXPECT_EQ(found.soup_pieces, 0u);
    ASSERT_GT(found.pairs.size(), 0u);
    for (const auto& [a, b] : found.pairs) {
        EXPECT_LT(a, b);
        const auto& ta = folded.triangles[a];
        const auto& tb = folded.triangles[b];
        // Each pair has one triangle of the moved vertex's fan.
        const bool fan_a = ta[0] == 0 || ta[1] == 0 || ta[2] == 0;
        const bool fan_b = tb[0] == 0 || tb[1] == 0 || tb[2] == 0;
        EXPECT_TRUE(fan_a || fan_b) << a << " " << b;
    }
    EXPECT_EQ(found.pairs_per_piece.at(0), found.pairs.size());
}

TEST(SelfIntersections, SeparatePiecesMayOverlap) {
    Mesh two = box({0, 0, 0}, {1, 1, 1});
    append(two, box({0.5f, 0.5f, 0.5f}, {1.5f, 1.5f, 1.5f}));
    const SelfIntersections found = find_self_intersections(two);
    EXPECT_EQ(found.pieces, 2u);
    EXPECT_EQ(found.pairs.size(), 0u);
    EXPECT_EQ(found.piece.at(0), 0u);
    EXPECT_EQ(found.piece.at(12), 1u);
}

TEST(SelfIntersections, OverlapsCountOncePiecesShareAVertex) {
    // A tetrahedron with its apex at the box's corner, reaching through the box: one piece
    // (the apex welds), no 2-manifold (two fans at one vertex), so tested as a soup.
    Mesh joined = box({0, 0, 0}, {1, 1, 1});
    Mesh spike;
    spike.positions = {{0, 0, 0}, {2, 0.5f, 0.5f}, {0.5f, 2, 0.5f}, {0.5f, 0.5f, 2}};
    spike.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    append(joined, spike);
    const SelfIntersections found = find_self_intersections(joined);
    EXPECT_EQ(found.pieces, 1u);
    EXPECT_EQ(found.soup_pieces, 1u);
    ASSERT_GT(found.pairs.size(), 0u);
    for (const auto& [a, b] : found.pairs) {
        EXPECT_LT(a, 12u);  // a box triangle against a spike triangle
        EXPECT_GE(b, 12u);
    }

    // Two boxes that only touch at a corner: one piece, nothing crossing.
    Mesh touching = box({0, 0, 0}, {1, 1, 1});
    append(touching, box({1, 1, 1}, {2, 2, 2}));
    const SelfIntersections touch = find_self_intersections(touching);
    EXPECT_EQ(touch.pieces, 1u);
    EXPECT_EQ(touch.soup_pieces, 1u);
    EXPECT_EQ(touch.pairs.size(), 0u);
}

TEST(SelfIntersections, DuplicatesCountAndDegenerateTrianglesAreListed) {
    Mesh doubled = box({0, 0, 0}, {1, 1, 1});
    doubled.triangles.push_back(doubled.triangles[3]);
    const SelfIntersections found = find_self_intersections(doubled);
    ASSERT_EQ(found.pairs.size(), 1u);
    EXPECT_EQ(found.pairs[0][0], 3u);
    EXPECT_EQ(found.pairs[0][1], 12u);

    Mesh flat = box({0, 0, 0}, {1, 1, 1});
    flat.positions.push_back({0.5f, 0.0f, 0.0f});  // on the edge from vertex 0 to 1
    flat.triangles.push_back({0, 1, 8});
    const SelfIntersections degenerate = find_self_intersections(flat);
    EXPECT_EQ(degenerate.pairs.size(), 0u);
    ASSERT_EQ(degenerate.degenerate.size(), 1u);
    EXPECT_EQ(degenerate.degenerate[0], 12u);
}

TEST(SelfIntersections, EmptyMeshHasNoPieces) {
    const SelfIntersections found = find_self_intersections(Mesh{});
    EXPECT_EQ(found.pieces, 0u);
    EXPECT_EQ(found.pairs.size(), 0u);
}

}  // namespace
}  // namespace sylva
