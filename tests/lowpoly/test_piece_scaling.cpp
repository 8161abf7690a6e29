// Reduced pieces grown back to their source's area: a coarse polyhedron inscribed in a ball
// grows until it shows the ball's mean outline; pieces without a single match stay put.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "core/mesh_checks.h"
#include "lowpoly/piece_scaling.h"
#include "quality/self_intersections.h"

namespace sylva {
namespace {

// A latitude-longitude ball of `rings` x 2 `rings` quads, its corners on the sphere,
// counter-clockwise from outside.
void append_ball(Mesh& mesh, glm::vec3 centre, float radius, int rings) {
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    const int around = 2 * rings;
    mesh.positions.push_back(centre + glm::vec3(0, radius, 0));
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < around; ++j) {
            const float t = std::numbers::pi_v<float> * static_cast<float>(i) / rings;
            const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / around;
            mesh.positions.push_back(centre + radius * glm::vec3(std::sin(t) * std::cos(a),
                                                                 std::cos(t),
                                                                 std::sin(t) * std::sin(a)));
        }
    mesh.positions.push_back(centre - glm::vec3(0, radius, 0));
    const auto bottom = static_cast<std::uint32_t>(mesh.positions.size() - 1);
    auto at = [&](int i, int j) {
        return first + 1 + static_cast<std::uint32_t>((i - 1) * around + (j % around));
    };
    for (int j = 0; j < around; ++j) {
        mesh.triangles.push_back({first, at(1, j + 1), at(1, j)});
        mesh.triangles.push_back({bottom, at(rings - 1, j), at(rings - 1, j + 1)});
    }
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < around; ++j) {
            mesh.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
}

// An octahedron with its corners on the sphere: what a ball reduced to 8 triangles is.
void append_octahedron(Mesh& mesh, glm::vec3 centre, float radius) {
    const auto f = static_cast<std::uint32_t>(mesh.positions.size());
    for (glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                        glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)})
        mesh.positions.push_back(centre + radius * d);
    const std::uint32_t faces[8][3] = {{0, 2, 4}, {4, 2, 1}, {1, 2, 5}, {5, 2, 0},
                                       {4, 3, 0}, {1, 3, 4}, {5, 3, 1}, {0, 3, 5}};
    for (const auto& t : faces) mesh.triangles.push_back({f + t[0], f + t[1], f + t[2]});
}

TEST(PieceScaling, AnInscribedOctahedronGrowsToTheBallsArea) {
    const glm::vec3 centre(1, 2, 3);
    Mesh ball, octahedron;
    append_ball(ball, centre, 0.5f, 16);
    append_octahedron(octahedron, centre, 0.5f);
    const double sphere = 4.0 * std::numbers::pi * 0.25;
    ASSERT_LT(surface_area(octahedron), 0.6 * sphere);  // what the reduction leaves

    const PieceScaling grown = restore_piece_areas(octahedron, ball, 2.0f);
    EXPECT_EQ(grown.scaled, 1u);
    EXPECT_NEAR(surface_area(octahedron), sphere, 0.03 * sphere);
    // Grown about its centre, and still sound.
    glm::vec3 mean(0.0f);
    for (const glm::vec3& p : octahedron.positions) mean += p / 6.0f;
    EXPECT_LT(glm::distance(mean, centre), 1e-5f);
    EXPECT_TRUE(check_topology(octahedron).is_closed_manifold());
    for (double volume : component_volumes(octahedron)) EXPECT_GT(volume, 0.0);
    EXPECT_TRUE(find_self_intersections(octahedron).pairs.empty());
}

TEST(PieceScaling, GrowsAtMostTheLimitAndNeverShrinks) {
    Mesh ball, small, large;
    append_ball(ball, glm::vec3(0.0f), 1.0f, 16);
    append_octahedron(small, glm::vec3(0.0f), 0.3f);  // would need 4.5 times
    restore_piece_areas(small, ball, 2.0f);
    EXPECT_NEAR(glm::length(small.positions[0]), 0.6f, 1e-5f);
    append_octahedron(large, glm::vec3(0.0f), 1.9f);  // larger than the ball already
    const Mesh before = large;
    EXPECT_EQ(restore_piece_areas(large, ball, 2.0f).scaled, 0u);
    EXPECT_EQ(large.positions, before.positions);
}

TEST(PieceScaling, EachPieceFollowsItsOwnSourceAndSplitPiecesStay) {
    // Two balls far apart; the first reduced to one octahedron, the second split in two.
    Mesh balls, reduced;
    append_ball(balls, glm::vec3(0, 0, 0), 0.5f, 12);
    append_ball(balls, glm::vec3(5, 0, 0), 1.0f, 12);
    append_octahedron(reduced, glm::vec3(0, 0, 0), 0.5f);
    append_octahedron(reduced, glm::vec3(4.6f, 0, 0), 0.3f);
    append_octahedron(reduced, glm::vec3(5.4f, 0, 0), 0.3f);
    const Mesh before = reduced;
    EXPECT_EQ(restore_piece_areas(reduced, balls, 2.0f).scaled, 1u);
    EXPECT_GT(glm::length(reduced.positions[0]), 0.6f);  // the first grew
    for (std::size_t v = 6; v < reduced.positions.size(); ++v)
        EXPECT_EQ(reduced.positions[v], before.positions[v]);
}

}  // namespace
}  // namespace sylva
