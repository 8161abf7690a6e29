#include <gtest/gtest.h>

#include <cmath>

#include "quality/folds.h"
#include "shapes.h"

namespace sylva {
namespace {

using test::box;
using test::flipped;
using test::icosphere;
using test::octahedron;
using test::prism;

double length(glm::vec2 a, glm::vec2 b) {
    return glm::length(b - a);
}

TEST(Folds, ConvexMeshesFoldNowhereInwards) {
    EXPECT_EQ(concave_fold_share(box({0, 0, 0}, {1, 2, 3}), 0.0), 0.0);
    EXPECT_EQ(concave_fold_share(icosphere(2), 0.0), 0.0);
    const Folds cube = measure_folds(box({0, 0, 0}, {1, 1, 1}));
    EXPECT_EQ(cube.interior_edges, 18u);  // 12 edges + 6 face diagonals
    EXPECT_NEAR(cube.interior_length, 12.0 + 6.0 * std::sqrt(2.0), 1e-9);
}

TEST(Folds, InsideOutEveryEdgeFolds) {
    // The octahedron's normals meet at 70.5 degrees across every edge, all of one length.
    EXPECT_EQ(concave_fold_share(octahedron(), 60.0), 0.0);
    EXPECT_NEAR(concave_fold_share(flipped(octahedron()), 60.0), 1.0, 1e-12);
    EXPECT_EQ(concave_fold_share(flipped(octahedron()), 71.0), 0.0);
}

// The prism's edges, by hand: the outline at the bottom and the top, the vertical edges,
// one diagonal per side wall and the caps' diagonals from the hub.
double prism_edge_length(const std::vector<glm::vec2>& polygon, double height,
                         const std::vector<glm::vec2>& cap_diagonal_ends, glm::vec2 hub) {
    double total = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const double side = length(polygon[i], polygon[(i + 1) % polygon.size()]);
        total += 2.0 * side + height + std::sqrt(side * side + height * height);
    }
    for (glm::vec2 end : cap_diagonal_ends) total += 2.0 * length(hub, end);
    return total;
}

TEST(Folds, NotchShareMatchesTheHandCount) {
    // A square prism with a narrow notch cut in from one side: the notch's bottom edge folds
    // inwards by 180 - 2 atan(0.5 / 3) = 161.08 degrees; every other edge is flat or convex.
    const std::vector<glm::vec2> notched = {{0, 0}, {4, 0},    {4, 4}, {2.5f, 4},
                                            {2, 1}, {1.5f, 4}, {0, 4}};
    const double height = 2.0;
    const Mesh mesh = prism(notched, static_cast<float>(height), 4);
    const double total =
        prism_edge_length(notched, height, {{0, 4}, {0, 0}, {4, 0}, {4, 4}}, notched[4]);
    const Folds folds = measure_folds(mesh);
    EXPECT_EQ(folds.folded_edges, 1u);
    EXPECT_NEAR(folds.interior_length, total, 1e-5);
    EXPECT_NEAR(folds.share, height / total, 1e-6);
    EXPECT_NEAR(concave_fold_share(mesh, 161.0), height / total, 1e-6);
    EXPECT_EQ(concave_fold_share(mesh, 161.2), 0.0);
    // Scaling changes no share.
    Mesh larger = mesh;
    for (glm::vec3& p : larger.positions) p *= 3.0f;
    EXPECT_NEAR(concave_fold_share(larger), height / total, 1e-6);
}

TEST(Folds, RightAngleNotchIsNotSharperThanNinety) {
    // An L: its inner corner folds inwards by exactly 90 degrees.
    const std::vector<glm::vec2> ell = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    const double height = 1.0;
    const Mesh mesh = prism(ell, static_cast<float>(height), 3);
    const double total = prism_edge_length(ell, height, {{0, 2}, {0, 0}, {2, 0}}, ell[3]);
    EXPECT_EQ(concave_fold_share(mesh, 90.0), 0.0);
    EXPECT_NEAR(concave_fold_share(mesh, 89.0), height / total, 1e-6);
}

TEST(Folds, OpenEdgesAndFlatFacesDoNotCount) {
    Mesh open = box({0, 0, 0}, {1, 1, 1});
    open.triangles.resize(10);  // one face gone: its four edges are now open
    const Folds folds = measure_folds(open, 0.0);
    EXPECT_EQ(folds.interior_edges, 18u - 5u);
    EXPECT_EQ(folds.share, 0.0);

    Mesh degenerate = box({0, 0, 0}, {1, 1, 1});
    degenerate.positions.push_back({0.5f, 0.0f, 0.0f});
    degenerate.triangles.push_back({0, 1, 8});  // no area: left out, edge 0-1 stays interior
    EXPECT_EQ(measure_folds(degenerate).interior_edges, 18u);
    EXPECT_EQ(measure_folds(Mesh{}).share, 0.0);
}

}  // namespace
}  // namespace sylva
