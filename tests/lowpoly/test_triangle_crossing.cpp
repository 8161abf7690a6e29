// The reduction's guard against self-intersections: when two triangles of a surface cross,
// and the grid that finds the faces near a collapse.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "lowpoly/face_grid.h"
#include "lowpoly/triangle_crossing.h"

namespace sylva {
namespace {

CrossingTriangle tri(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    return crossing_triangle(a, b, c);
}

TEST(TrianglesCross, ThroughEachOtherApartAndInOnePlane) {
    const CrossingTriangle flat = tri({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
    // A triangle standing through the middle of `flat`.
    EXPECT_TRUE(triangles_cross(flat, tri({0.5, 0.5, -1}, {0.5, 0.5, 1}, {0.6, 0.4, 1}), 0));
    // The same lifted off it.
    EXPECT_FALSE(triangles_cross(flat, tri({0.5, 0.5, 0.1}, {0.5, 0.5, 1}, {0.6, 0.4, 1}), 0));
    // Beside it, piercing its plane outside the triangle.
    EXPECT_FALSE(triangles_cross(flat, tri({3, 3, -1}, {3, 3, 1}, {3.1, 2.9, 1}), 0));
    // Lying in its plane, overlapping: taken as apart (the normal guard's business).
    EXPECT_FALSE(triangles_cross(flat, tri({0.1, 0.1, 0}, {1, 0.1, 0}, {0.1, 1, 0}), 0));
    // Touching counts as crossing: a corner resting on the face.
    EXPECT_TRUE(triangles_cross(flat, tri({0.5, 0.5, 0}, {0.5, 0.5, 1}, {0.6, 0.4, 1}), 0));
}

TEST(TrianglesCross, ASharedCornerCrossesOnlyThroughTheOppositeEdges) {
    const CrossingTriangle a = tri({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
    // Sharing corner 0 and folding up: apart.
    const CrossingTriangle up = tri({0, 0, 0}, {1, 1, 1}, {-1, 1, 1});
    EXPECT_FALSE(triangles_cross(a, up, 1, 0, 0));
    // Sharing corner 0 and passing its far edge through a's inside: crossing.
    const CrossingTriangle through = tri({0, 0, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1});
    EXPECT_TRUE(triangles_cross(a, through, 1, 0, 0));
    // The shared corner named at other places gives the same answer.
    const CrossingTriangle turned = tri({0.5, 0.5, 1}, {0, 0, 0}, {0.5, 0.5, -1});
    EXPECT_TRUE(triangles_cross(a, turned, 1, 0, 1));
    // Two triangles sharing an edge are apart by definition.
    EXPECT_FALSE(triangles_cross(a, tri({0, 0, 0}, {2, 0, 0}, {1, -1, 0.5}), 2));
}

TEST(TrianglesCross, ScaleDoesNotChangeTheAnswer) {
    for (const double s : {1e-4, 1.0, 1e4}) {
        const CrossingTriangle a = tri({0, 0, 0}, {2 * s, 0, 0}, {0, 2 * s, 0});
        EXPECT_TRUE(triangles_cross(
            a, tri({0.5 * s, 0.5 * s, -s}, {0.5 * s, 0.5 * s, s}, {0.6 * s, 0.4 * s, s}), 0));
        EXPECT_FALSE(triangles_cross(
            a, tri({0.5 * s, 0.5 * s, 0.1 * s}, {0.5 * s, 0.5 * s, s}, {0.6 * s, 0.4 * s, s}), 0));
    }
}

std::vector<std::uint32_t> near(const FaceGrid& grid, glm::dvec3 lo, glm::dvec3 hi) {
    std::vector<std::uint32_t> found;
    grid.near(lo, hi, [&](std::uint32_t f) { found.push_back(f); });
    std::sort(found.begin(), found.end());
    return found;
}

TEST(FaceGrid, FindsTheFacesWhoseCellsMeetABoxOnce) {
    FaceGrid grid;
    grid.reset(1.0, 4);
    grid.place(0, {0.1, 0.1, 0.1}, {0.4, 0.4, 0.4});
    grid.place(1, {0.2, 0.2, 0.2}, {2.5, 0.3, 0.3});  // three cells
    grid.place(2, {5.1, 5.1, 5.1}, {5.2, 5.2, 5.2});
    EXPECT_EQ(near(grid, {0, 0, 0}, {0.5, 0.5, 0.5}), (std::vector<std::uint32_t>{0, 1}));
    EXPECT_EQ(near(grid, {2.1, 0, 0}, {2.2, 0.5, 0.5}), (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(near(grid, {5, 5, 5}, {5.5, 5.5, 5.5}), (std::vector<std::uint32_t>{2}));
    grid.remove(1);
    EXPECT_EQ(near(grid, {2.1, 0, 0}, {2.2, 0.5, 0.5}), (std::vector<std::uint32_t>{}));
    grid.place(1, {5.3, 5.3, 5.3}, {5.4, 5.4, 5.4});  // moved
    EXPECT_EQ(near(grid, {5, 5, 5}, {5.5, 5.5, 5.5}), (std::vector<std::uint32_t>{1, 2}));
    // A face larger than the cells it may list in is found by every query.
    grid.place(3, {-100, -100, -100}, {100, 100, 100});
    EXPECT_EQ(near(grid, {50, 50, 50}, {50.1, 50.1, 50.1}), (std::vector<std::uint32_t>{3}));
    grid.remove(3);
    EXPECT_EQ(near(grid, {50, 50, 50}, {50.1, 50.1, 50.1}), (std::vector<std::uint32_t>{}));
}

}  // namespace
}  // namespace sylva
