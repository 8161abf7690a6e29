// Space colonization (Liebemann 2017, chapter 3): properties of the node graph, the
// envelopes and points, and the skeleton built from it.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <vector>

#include "colonization/attraction_points.h"
#include "colonization/branch_shaping.h"
#include "colonization/envelope.h"
#include "colonization/space_colonization.h"
#include "core/random.h"

namespace sylva {
namespace {

constexpr float kPi = 3.14159265f;

ColonizationSettings crown_settings() {
    ColonizationSettings s;
    s.influence_radius = 1.5f;
    s.kill_distance = 0.4f;
    s.step_size = 0.25f;
    s.trunk_height = 2.0f;
    return s;
}

Envelope crown_envelope(EnvelopeShape shape = EnvelopeShape::Ellipsoid) {
    Envelope e;
    e.shape = shape;
    e.size = {6.0f, 5.0f, 6.0f};
    e.base = {0.0f, 2.5f, 0.0f};
    return e;
}

ColonizationGraph grow_crown(const ColonizationSettings& s, std::uint64_t seed = 7,
                             int count = 3000) {
    const auto points =
        attraction_points(crown_envelope(), count, PointDistribution::Uniform, seed);
    return colonize(points, glm::vec3(0.0f), s);
}

float nearest_node(const ColonizationGraph& g, const glm::vec3& p) {
    float best = INFINITY;
    for (const ColonizationNode& n : g.nodes) best = std::min(best, glm::distance(n.position, p));
    return best;
}

// The ring of Liebemann 2017, Fig. 3.2: N random points in an annulus of outer radius r (in the
// plane z = 0), the root on its bottom edge.
std::vector<glm::vec3> ring(int count, float r, std::uint64_t seed) {
    Random random(seed);
    std::vector<glm::vec3> points;
    while (static_cast<int>(points.size()) < count) {
        const float x = static_cast<float>(2.0 * random.uniform() - 1.0) * r;
        const float y = static_cast<float>(2.0 * random.uniform() - 1.0) * r;
        const float d = std::hypot(x, y);
        if (d <= r && d >= 0.5f * r) points.push_back({x, y + r, 0.0f});
    }
    return points;
}

TEST(Envelope, PointsLieInsideEveryShapeAndAreSeeded) {
    for (EnvelopeShape shape :
         {EnvelopeShape::Sphere, EnvelopeShape::Ellipsoid, EnvelopeShape::Cone,
          EnvelopeShape::Cylinder, EnvelopeShape::Hemisphere}) {
        for (PointDistribution d : {PointDistribution::Uniform, PointDistribution::Halton}) {
            const Envelope e = crown_envelope(shape);
            const auto a = attraction_points(e, 500, d, 3);
            ASSERT_EQ(a.size(), 500u);
            for (const glm::vec3& p : a) EXPECT_TRUE(inside(e, p));
            EXPECT_EQ(a, attraction_points(e, 500, d, 3));
            EXPECT_NE(a, attraction_points(e, 500, d, 4));
        }
    }
    // The cone narrows to its apex; the hemisphere has a flat bottom.
    EXPECT_TRUE(inside(crown_envelope(EnvelopeShape::Cone), {2.9f, 2.6f, 0.0f}));
    EXPECT_FALSE(inside(crown_envelope(EnvelopeShape::Cone), {2.9f, 7.0f, 0.0f}));
    EXPECT_FALSE(inside(crown_envelope(EnvelopeShape::Hemisphere), {0.0f, 2.4f, 0.0f}));
}

TEST(Colonization, NoAttractionPointIsLeftWithinKillDistance) {
    const ColonizationSettings s = crown_settings();
    const ColonizationGraph g = grow_crown(s);
    EXPECT_NE(g.stop, ColonizationStop::MaxIterations);
    EXPECT_GT(g.nodes.size(), 200u);
    for (const glm::vec3& p : g.remaining) EXPECT_GT(nearest_node(g, p), s.kill_distance);
    // Colonised: hardly any point is left (those left are out of every node's reach).
    EXPECT_LT(g.remaining.size(), 3000u / 20);
}

TEST(Colonization, EveryNewNodeIsOneStepFromItsParent) {
    ColonizationSettings s = crown_settings();
    s.tropism = {0.0f, -0.3f, 0.0f};
    const ColonizationGraph g = grow_crown(s);
    for (size_t i = 1; i < g.nodes.size(); ++i) {
        const ColonizationNode& n = g.nodes[i];
        EXPECT_NEAR(glm::distance(n.position, g.nodes[size_t(n.parent)].position), s.step_size,
                    1e-4f);
    }
    // Weighted growth: 2D on the trunk (depth 0), D at max_Z.
    s.weighted_growth = true;
    s.max_depth = 4;
    const ColonizationGraph w = grow_crown(s);
    int deepest = 0;
    for (size_t i = 1; i < w.nodes.size(); ++i) {
        const ColonizationNode& parent = w.nodes[size_t(w.nodes[i].parent)];
        const float expected = s.step_size * (2.0f - float(parent.depth) / 4.0f);
        EXPECT_NEAR(glm::distance(w.nodes[i].position, parent.position), expected, 1e-4f);
        deepest = std::max(deepest, parent.depth);
    }
    EXPECT_GE(deepest, 2);
}

TEST(Colonization, TheGraphAndTheSkeletonAreOneTree) {
    ColonizationGraph g = grow_crown(crown_settings());
    ASSERT_FALSE(g.nodes.empty());
    EXPECT_EQ(g.nodes[0].parent, -1);
    for (size_t i = 1; i < g.nodes.size(); ++i) {
        EXPECT_GE(g.nodes[i].parent, 0);
        EXPECT_LT(g.nodes[i].parent, int(i));  // parents first: no cycles
    }
    draw_successors_together(g, 0.5f);
    reduce_curves(g, 0.995f);
    const Skeleton skeleton = to_skeleton(g, 0.01f, 2.5f);
    ASSERT_EQ(skeleton.segments.size(), g.nodes.size() - 1);
    for (size_t i = 0; i < skeleton.segments.size(); ++i) {
        const Segment& s = skeleton.segments[i];
        if (s.parent < 0) {
            EXPECT_EQ(s.a, g.nodes[0].position);
        } else {
            ASSERT_LT(s.parent, int(i));
            EXPECT_EQ(s.a, skeleton.segments[size_t(s.parent)].b);
        }
    }
    // Murray's rule (eq. 3.4) at the first fork below the crown: r^g = sum of children's.
    std::vector<double> sum(skeleton.segments.size(), 0.0);
    std::vector<int> children(skeleton.segments.size(), 0);
    for (const Segment& s : skeleton.segments)
        if (s.parent >= 0) {
            sum[size_t(s.parent)] += std::pow(double(s.ra), 2.5);
            ++children[size_t(s.parent)];
        }
    for (size_t i = 0; i < skeleton.segments.size(); ++i) {
        if (children[i] == 0) {
            EXPECT_FLOAT_EQ(skeleton.segments[i].ra, 0.01f);
        } else {
            EXPECT_NEAR(std::pow(double(skeleton.segments[i].ra), 2.5), sum[i], 1e-6 * sum[i]);
        }
    }
}

TEST(Colonization, BranchDepthFollowsEquation35) {
    const ColonizationGraph g = grow_crown(crown_settings());
    std::vector<int> seen(g.nodes.size(), 0);  // successors met so far, in creation order
    EXPECT_EQ(g.nodes[0].depth, 0);
    int deepest = 0;
    for (size_t i = 1; i < g.nodes.size(); ++i) {
        const auto p = size_t(g.nodes[i].parent);
        const int expected = seen[p]++ == 0 ? g.nodes[p].depth : g.nodes[p].depth + 1;
        EXPECT_EQ(g.nodes[i].depth, expected) << i;
        deepest = std::max(deepest, g.nodes[i].depth);
    }
    EXPECT_GT(deepest, 2);
}

TEST(Colonization, MaxDegreeMaxDepthAndNoGrowAreRespected) {
    ColonizationSettings s = crown_settings();
    s.max_degree = 2;
    s.max_depth = 3;
    s.max_no_grow = 4;
    const ColonizationGraph g = grow_crown(s);
    EXPECT_GT(g.nodes.size(), 50u);
    // Successors are born no more than max_NG iterations after their parent's last growth.
    std::vector<int> last_growth(g.nodes.size(), 0);
    for (size_t i = 0; i < g.nodes.size(); ++i) last_growth[i] = g.nodes[i].born;
    for (size_t i = 0; i < g.nodes.size(); ++i) {
        const ColonizationNode& n = g.nodes[i];
        EXPECT_LE(n.successors, 2);
        EXPECT_LE(n.depth, 3);
        if (n.parent < 0) continue;
        const auto p = size_t(n.parent);
        EXPECT_LE(n.born - last_growth[p], s.max_no_grow) << i;
        last_growth[p] = n.born;
    }
}

TEST(Colonization, GridAndBruteForceGrowTheSameTree) {
    ColonizationSettings s = crown_settings();
    s.max_no_grow = 3;  // nodes going idle exercise the grid's re-queries
    const ColonizationGraph grid = grow_crown(s);
    s.search = NearestSearch::BruteForce;
    const ColonizationGraph brute = grow_crown(s);
    ASSERT_EQ(grid.nodes.size(), brute.nodes.size());
    for (size_t i = 0; i < grid.nodes.size(); ++i) {
        EXPECT_EQ(grid.nodes[i].position, brute.nodes[i].position) << i;
        EXPECT_EQ(grid.nodes[i].parent, brute.nodes[i].parent) << i;
    }
    EXPECT_EQ(grid.remaining, brute.remaining);
}

TEST(Colonization, SameSeedSameBytes) {
    const ColonizationGraph a = grow_crown(crown_settings(), 11);
    const ColonizationGraph b = grow_crown(crown_settings(), 11);
    const ColonizationGraph c = grow_crown(crown_settings(), 12);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(
        0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(ColonizationNode)));
    EXPECT_TRUE(a.nodes.size() != c.nodes.size() ||
                std::memcmp(a.nodes.data(), c.nodes.data(),
                            a.nodes.size() * sizeof(ColonizationNode)) != 0);
}

TEST(Colonization, Seed000Figure32RingTerminatesAndIsColonised) {
    const auto points = ring(2000, 500.0f, 32);
    ColonizationSettings s;
    s.influence_radius = 100.0f;
    s.kill_distance = 20.0f;
    s.step_size = 15.0f;
    s.max_iterations = 100000;
    const ColonizationGraph g = colonize(points, glm::vec3(0.0f), s);
    EXPECT_NE(g.stop, ColonizationStop::MaxIterations);
    EXPECT_LT(g.remaining.size(), 2000u / 50) << "the ring is colonised";
    // The tree reaches all the way round: up to the ring's top.
    float top = 0.0f;
    for (const ColonizationNode& n : g.nodes) top = std::max(top, n.position.y);
    EXPECT_GT(top, 900.0f);
    for (const ColonizationNode& n : g.nodes) EXPECT_EQ(n.position.z, 0.0f);  // stays planar
}

TEST(Colonization, EquallyDistantPointsDoNotMakeItOscillate) {
    // Liebemann 2017, 5.3: a node between two points at the same distance.
    ColonizationSettings s;
    s.influence_radius = 3.0f;
    s.kill_distance = 0.1f;
    s.step_size = 0.3f;
    s.max_iterations = 100000;
    const std::vector<glm::vec3> opposite = {{-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    ColonizationGraph g = colonize(opposite, glm::vec3(0.0f), s);
    EXPECT_EQ(g.stop, ColonizationStop::NothingGrew);
    EXPECT_GE(g.oscillations, 1);
    // Above the root: the tree grows up between them, then would go back and forth.
    const std::vector<glm::vec3> above = {{-1.0f, 1.0f, 0.0f}, {1.0f, 1.0f, 0.0f}};
    g = colonize(above, glm::vec3(0.0f), s);
    EXPECT_NE(g.stop, ColonizationStop::MaxIterations);
    EXPECT_LT(g.iterations, 20);
    // Ties in a grid of points at one distance from many nodes, with tropism.
    std::vector<glm::vec3> lattice;
    for (int x = -3; x <= 3; ++x)
        for (int y = 1; y <= 6; ++y)
            for (int z = -3; z <= 3; ++z) lattice.push_back({float(x), float(y), float(z)});
    s.tropism = {0.0f, -0.5f, 0.0f};
    s.kill_distance = 0.2f;
    g = colonize(lattice, glm::vec3(0.0f), s);
    EXPECT_NE(g.stop, ColonizationStop::MaxIterations);
}

TEST(Colonization, CurveReductionKeepsTheShapeWithFewerNodes) {
    ColonizationGraph g = grow_crown(crown_settings());
    const size_t before = g.nodes.size();
    const size_t tips_before = tips(to_skeleton(g, 0.01f, 2.0f)).size();
    reduce_curves(g, 0.99f);
    EXPECT_LT(g.nodes.size(), before);
    EXPECT_EQ(tips(to_skeleton(g, 0.01f, 2.0f)).size(), tips_before);  // no tip removed
    reduce_curves(g, 1.0f);                                            // 1 keeps every node
}

TEST(Colonization, ACancelledRunThrows) {
    std::atomic<bool> cancel{true};
    ColonizationSettings s = crown_settings();
    s.cancel = &cancel;
    EXPECT_THROW(grow_crown(s), Cancelled);
}

}  // namespace
}  // namespace sylva
