// Prism tubes: closed, outward, the triangle count they promise, no faces crossing, as wide
// on average as the branch they stand for, and axes simplified and split where they must be.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <numbers>

#include "core/mesh_checks.h"
#include "lowpoly/prism_tube.h"
#include "quality/self_intersections.h"

namespace sylva {
namespace {

TubeAxis axis_of(std::vector<glm::vec3> points, float radius, bool pointed = false) {
    TubeAxis axis;
    axis.radii.assign(points.size(), radius);
    axis.points = std::move(points);
    axis.pointed = pointed;
    return axis;
}

// Every piece of the axis appended as a tube: one closed, outward piece each, no faces
// crossing inside one, as many triangles as tube_triangles() says.
Mesh expect_sound_tubes(const TubeAxis& axis, int sides) {
    Mesh mesh;
    std::size_t promised = 0;
    for (const TubeAxis& piece : tube_pieces(axis, sides)) {
        append_tube(mesh, piece, sides, glm::vec3(1, 0, 0));
        promised += tube_triangles(piece.points.size(), sides, piece.pointed);
    }
    EXPECT_EQ(mesh.triangles.size(), promised);
    EXPECT_TRUE(check_topology(mesh).is_closed_manifold()) << to_string(check_topology(mesh));
    for (double volume : component_volumes(mesh)) EXPECT_GT(volume, 0.0);
    EXPECT_TRUE(find_self_intersections(mesh).pairs.empty());
    return mesh;
}

TEST(PrismTube, AStraightTubeIsAClosedOutwardPrism) {
    for (int sides = 3; sides <= 8; ++sides) {
        const Mesh mesh =
            expect_sound_tubes(axis_of({{0, 0, 0}, {0, 1, 0}, {0, 2, 0}}, 0.1f), sides);
        // Two caps of sides - 2 triangles and two triangles per side and segment.
        EXPECT_EQ(mesh.triangles.size(), static_cast<std::size_t>(2 * (sides - 2) + 2 * 2 * sides));
    }
}

TEST(PrismTube, APointedTubeEndsJustPastItsLastPoint) {
    const Mesh mesh =
        expect_sound_tubes(axis_of({{0, 0, 0}, {0, 1, 0}, {0.2f, 2, 0}}, 0.1f, true), 3);
    // A quarter of the last segment on (the tip as thick as the point before it), so the
    // cone shows more of the branch's last segment than one ending on the tip would.
    const glm::vec3 point = mesh.positions.back();
    EXPECT_NEAR(point.x, 0.25f, 1e-5f);
    EXPECT_NEAR(point.y, 2.25f, 1e-5f);
    // A tip half as thick as the point before it: an eighth of the segment on.
    TubeAxis thinning = axis_of({{0, 0, 0}, {0, 1, 0}}, 0.1f, true);
    thinning.radii.back() = 0.05f;
    EXPECT_NEAR(expect_sound_tubes(thinning, 4).positions.back().y, 1.125f, 1e-5f);
    // One segment of a triangle ending in a point is a tetrahedron.
    EXPECT_EQ(expect_sound_tubes(axis_of({{0, 0, 0}, {0, 1, 0}}, 0.1f, true), 3).triangles.size(),
              4u);
}

TEST(PrismTube, ABendingAxisStaysOnePieceWithoutCrossingFaces) {
    // A branch curving through 60 degrees in four bends of 15, with a taper.
    TubeAxis axis;
    glm::vec3 p(0.0f), d(0, 1, 0);
    for (int i = 0; i < 6; ++i) {
        axis.points.push_back(p);
        axis.radii.push_back(0.12f - 0.015f * static_cast<float>(i));
        p += 0.5f * d;
        const float a = glm::radians(15.0f);
        d = glm::vec3(d.x * std::cos(a) + d.y * std::sin(a), d.y * std::cos(a) - d.x * std::sin(a),
                      0.0f);
    }
    axis.pointed = true;
    EXPECT_EQ(tube_pieces(axis, 5).size(), 1u);
    expect_sound_tubes(axis, 5);
}

TEST(PrismTube, SharpBendsAndShortSegmentsSplitTheAxis) {
    // A hairpin: 150 degrees at the middle point.
    const TubeAxis hairpin = axis_of({{0, 0, 0}, {0, 1, 0}, {0.5f, 0.134f, 0}}, 0.05f);
    EXPECT_EQ(tube_pieces(hairpin, 4).size(), 2u);
    expect_sound_tubes(hairpin, 4);
    // A 60-degree bend on a segment shorter than its mitre reaches.
    const TubeAxis stubby =
        axis_of({{0, 0, 0}, {0, 0.1f, 0}, {0.08f, 0.15f, 0}, {0.08f, 1, 0}}, 0.2f);
    EXPECT_GE(tube_pieces(stubby, 6).size(), 2u);
    expect_sound_tubes(stubby, 6);
    // Repeated points are dropped; a single point makes no tube.
    EXPECT_EQ(tube_pieces(axis_of({{0, 0, 0}, {0, 0, 0}}, 0.1f), 3).size(), 0u);
    EXPECT_EQ(tube_pieces(axis_of({{0, 0, 0}, {0, 0, 0}, {0, 1, 0}}, 0.1f), 3)[0].points.size(),
              2u);
}

TEST(PrismTube, ItsMeanWidthIsTheBranchDiameter) {
    // The width seen from every direction across the axis, averaged: what a branch shows.
    for (int sides : {3, 4, 6}) {
        Mesh mesh;
        append_tube(mesh, axis_of({{0, 0, 0}, {0, 1, 0}}, 0.5f), sides, glm::vec3(1, 0, 0));
        double sum = 0.0;
        constexpr int kViews = 360;
        for (int v = 0; v < kViews; ++v) {
            const double a = 2.0 * std::numbers::pi * v / kViews;
            const glm::vec3 across(static_cast<float>(std::cos(a)), 0,
                                   static_cast<float>(std::sin(a)));
            float low = 1e9f, high = -1e9f;
            for (const glm::vec3& p : mesh.positions) {
                low = std::min(low, glm::dot(p, across));
                high = std::max(high, glm::dot(p, across));
            }
            sum += high - low;
        }
        EXPECT_NEAR(sum / kViews, 1.0, 0.01) << sides << " sides";
    }
}

TEST(PrismTube, SimplifyingKeepsBendsAndRadiusStepsAndDropsTheRest) {
    TubeAxis axis = axis_of({{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, {0, 3, 0}, {1, 4, 0}}, 0.1f);
    const TubeAxis straight = simplify_axis(axis, 0.01f);
    ASSERT_EQ(straight.points.size(), 3u);  // the collinear middle points go, the bend stays
    EXPECT_EQ(straight.points[1], glm::vec3(0, 3, 0));
    axis.radii[1] = 0.5f;  // a step in the radius is kept (and the points that end it)
    const TubeAxis stepped = simplify_axis(axis, 0.01f);
    ASSERT_GT(stepped.points.size(), 3u);
    EXPECT_EQ(stepped.radii[1], 0.5f);
    // With a tolerance wider than the bend, only the ends remain.
    EXPECT_EQ(simplify_axis(axis, 10.0f).points.size(), 2u);
}

// A radius off the line by more than half the tolerance widens the branch by more than the
// tolerance (on both sides): it stays; one off by less goes.
TEST(PrismTube, ARadiusErrorCountsTwiceAsItShowsOnBothSides) {
    TubeAxis axis = axis_of({{0, 0, 0}, {0, 1, 0}, {0, 2, 0}}, 0.1f);
    axis.radii[1] = 0.1f + 0.6f * 0.01f;
    EXPECT_EQ(simplify_axis(axis, 0.01f).points.size(), 3u);
    axis.radii[1] = 0.1f + 0.4f * 0.01f;
    EXPECT_EQ(simplify_axis(axis, 0.01f).points.size(), 2u);
}

}  // namespace
}  // namespace sylva
