// Regions and roots: an envelope given as any solid (an SDF's inside), a tilted
// envelope, an obstacle no point lies in and no node grows into, and several roots each
// growing one tree of a forest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <set>
#include <string>
#include <vector>

#include "colonization/attraction_points.h"
#include "colonization/colonization_growth.h"
#include "colonization/envelope.h"
#include "colonization/obstacle.h"
#include "colonization/space_colonization.h"
#include "core/errors.h"

namespace sylva {
namespace {

ColonizationSettings crown_settings() {
    ColonizationSettings s;
    s.influence_radius = 1.5f;
    s.kill_distance = 0.4f;
    s.step_size = 0.25f;
    s.trunk_height = 2.0f;
    return s;
}

// Two overlapping balls as a signed distance: the kind of field a template's crown is.
float two_balls(const glm::vec3& p) {
    return std::min(glm::distance(p, {-1.5f, 4.0f, 0.0f}) - 2.0f,
                    glm::distance(p, {1.5f, 5.0f, 0.0f}) - 1.5f);
}

TreeTemplate colonization_template() {
    TreeTemplate t;
    t.name = "test";
    t.growth = "colonization";
    ColonizationParams& c = t.params.blocks.edit<ColonizationParams>();
    c.attraction_points = 1500;
    c.trunk_height = 1.5;
    return t;
}

TEST(Envelope, AnSdfsInsideIsAnEnvelope) {
    const Region balls{{{-3.5f, 2.0f, -2.0f}, {3.0f, 6.5f, 2.0f}},
                       [](const glm::vec3& p) { return two_balls(p) < 0.0f; }};
    for (PointDistribution d : {PointDistribution::Uniform, PointDistribution::Halton}) {
        const auto points = attraction_points(balls, 800, d, 5);
        ASSERT_EQ(points.size(), 800u);
        for (const glm::vec3& p : points) EXPECT_LT(two_balls(p), 0.0f);
        EXPECT_EQ(points, attraction_points(balls, 800, d, 5));
    }
    // An envelope's region places the very points the envelope does.
    const Envelope e;
    EXPECT_EQ(attraction_points(region(e), 500, PointDistribution::Uniform, 2),
              attraction_points(e, 500, PointDistribution::Uniform, 2));
    const auto points = attraction_points(balls, 1500, PointDistribution::Uniform, 5);
    const ColonizationGraph g = colonize(points, glm::vec3(0.0f), crown_settings());
    EXPECT_GT(g.nodes.size(), 100u);
    EXPECT_LT(g.remaining.size(), 1500u / 10);
}

TEST(Envelope, TiltMovesTheTopSideways) {
    Envelope upright;
    upright.shape = EnvelopeShape::Cone;
    upright.size = {4.0f, 6.0f, 4.0f};
    upright.base = {0.0f, 2.0f, 0.0f};
    Envelope leaning = upright;
    leaning.tilt = 30.0f;
    const float s = std::sin(glm::radians(30.0f)), c = std::cos(glm::radians(30.0f));
    // Near the apex: upright straight above the base, leaning towards +x.
    const glm::vec3 apex_upright = upright.base + glm::vec3(0.0f, 5.5f, 0.0f);
    const glm::vec3 apex_leaning = upright.base + 5.5f * glm::vec3(s, c, 0.0f);
    EXPECT_TRUE(inside(upright, apex_upright));
    EXPECT_FALSE(inside(leaning, apex_upright));
    EXPECT_TRUE(inside(leaning, apex_leaning));
    EXPECT_FALSE(inside(upright, apex_leaning));
    EXPECT_TRUE(inside(leaning, upright.base + glm::vec3(0.0f, 0.1f, 0.0f)));  // same foot
    // The box follows, and the crown's top points sit to the +x side.
    const Box box = bounds(leaning);
    EXPECT_GT(box.max.x, bounds(upright).max.x + 0.5f);
    EXPECT_NEAR(box.max.x, 2.0f * c + 6.0f * s, 1e-4f);
    const auto points = attraction_points(leaning, 2000, PointDistribution::Halton, 1);
    ASSERT_EQ(points.size(), 2000u);
    float top_x = 0.0f;
    int top = 0;
    for (const glm::vec3& p : points) {
        EXPECT_TRUE(inside(leaning, p));
        if (p.y > upright.base.y + 3.0f) top_x += p.x, ++top;
    }
    ASSERT_GT(top, 0);
    EXPECT_GT(top_x / float(top), 1.0f);
    // Negative tilt leans the other way.
    leaning.tilt = -30.0f;
    EXPECT_TRUE(inside(leaning, upright.base + 5.5f * glm::vec3(-s, c, 0.0f)));
}

TEST(Obstacle, NoPointInItAndNoNodeGrowsIntoIt) {
    for (ObstacleShape shape : {ObstacleShape::Sphere, ObstacleShape::Box}) {
        TreeTemplate t = colonization_template();
        ColonizationParams& c = t.params.blocks.edit<ColonizationParams>();
        c.obstacle = shape;
        c.obstacle_center = {1.2, 5.0, 0.0};
        c.obstacle_size = {2.5, 2.0, 6.0};
        const Obstacle obstacle = template_obstacle(c);
        EXPECT_TRUE(inside(obstacle, {1.2f, 5.0f, 0.0f}));
        EXPECT_FALSE(inside(obstacle, {1.2f, 6.1f, 0.0f}));
        const ColonizationSettings settings = colonization_settings(t.params);
        ASSERT_TRUE(settings.blocked);

        const Envelope envelope = template_envelope(colonization_params(t.params));
        const Region region{bounds(envelope), [&](const glm::vec3& p) {
                                return inside(envelope, p) && !inside(obstacle, p);
                            }};
        const auto points = attraction_points(region, 1500, PointDistribution::Uniform, 3);
        ASSERT_EQ(points.size(), 1500u);
        for (const glm::vec3& p : points) EXPECT_FALSE(inside(obstacle, p));
        const ColonizationGraph g = colonize(points, glm::vec3(0.0f), settings);
        EXPECT_GT(g.nodes.size(), 100u);
        for (const ColonizationNode& n : g.nodes) EXPECT_FALSE(inside(obstacle, n.position));

        // The same through the growth method: the skeleton's nodes avoid it too.
        const Skeleton skeleton = colonization_growth.grow(t, {});
        EXPECT_GT(tips(skeleton).size(), 10u);
        for (const Segment& s : skeleton.segments) EXPECT_FALSE(inside(obstacle, s.b));
        // Without it the crown grows there: the test bites.
        t.params.blocks.edit<ColonizationParams>().obstacle = ObstacleShape::None;
        const Skeleton free = colonization_growth.grow(t, {});
        EXPECT_TRUE(std::any_of(free.segments.begin(), free.segments.end(),
                                [&](const Segment& s) { return inside(obstacle, s.b); }));
    }
    // A trunk under the obstacle stops below it.
    ColonizationSettings s = crown_settings();
    const Obstacle slab{ObstacleShape::Box, {0.0f, 1.0f, 0.0f}, {1.0f, 0.2f, 1.0f}};
    s.blocked = [&](const glm::vec3& p) { return inside(slab, p); };
    const std::vector<glm::vec3> above = {{0.0f, 3.0f, 0.0f}};
    const ColonizationGraph g = colonize(above, glm::vec3(0.0f), s);
    for (const ColonizationNode& n : g.nodes) EXPECT_LT(n.position.y, 0.9f);
}

TEST(Roots, NRootsGrowNTrees) {
    for (int count : {2, 3, 5}) {
        TreeTemplate t = colonization_template();
        ColonizationParams& c = t.params.blocks.edit<ColonizationParams>();
        c.roots = count;
        c.root_spread = 1.5;
        const std::vector<glm::vec3> roots = template_roots(c);
        ASSERT_EQ(roots.size(), size_t(count));
        for (const glm::vec3& r : roots) {
            EXPECT_NEAR(std::hypot(r.x, r.z), 1.5f, 1e-5f);
            EXPECT_EQ(r.y, 0.0f);
        }
        const Skeleton skeleton = colonization_growth.grow(t, {});
        // Each segment's parent exists and comes first; the parent-less ones start at a
        // root, and every root carries a tree.
        std::vector<int> tree_of(skeleton.segments.size(), -1);
        std::set<int> roots_used;
        std::vector<int> segments_per_tree(size_t(count), 0);
        for (size_t i = 0; i < skeleton.segments.size(); ++i) {
            const Segment& s = skeleton.segments[i];
            if (s.parent < 0) {
                const auto at = std::find(roots.begin(), roots.end(), s.a);
                ASSERT_NE(at, roots.end()) << "segment " << i << " starts off every root";
                tree_of[i] = int(at - roots.begin());
                roots_used.insert(tree_of[i]);
            } else {
                ASSERT_LT(s.parent, int(i));
                EXPECT_EQ(s.a, skeleton.segments[size_t(s.parent)].b);
                tree_of[i] = tree_of[size_t(s.parent)];
            }
            ++segments_per_tree[size_t(tree_of[i])];
        }
        EXPECT_EQ(roots_used.size(), size_t(count));
        for (int n : segments_per_tree) EXPECT_GT(n, 3);  // every trunk reached the crown
    }
    // One root stands at the origin whatever the spread.
    ColonizationParams p;
    p.root_spread = 3.0;
    EXPECT_EQ(template_roots(p), std::vector<glm::vec3>{glm::vec3(0.0f)});
}

TEST(Envelope, ATemplatesCrownNeedsTheTemplateLibrary) {
    TreeTemplate t = colonization_template();
    t.params.blocks.edit<ColonizationParams>().envelope = EnvelopeChoice::Template;
    EXPECT_THROW(colonization_growth.grow(t, {}), InputError);
    // Given a crown, the method fills it.
    GrowthContext context;
    std::string asked;
    context.template_crown = [&](std::string_view name) {
        asked = name;
        return Region{{{-3.5f, 2.0f, -2.0f}, {3.0f, 6.5f, 2.0f}},
                      [](const glm::vec3& p) { return two_balls(p) < 0.0f; }};
    };
    t.params.blocks.edit<ColonizationParams>().envelope_template = 1;
    const Skeleton skeleton = colonization_growth.grow(t, context);
    EXPECT_EQ(asked, envelope_template_names()[1]);
    EXPECT_GT(tips(skeleton).size(), 10u);
}

}  // namespace
}  // namespace sylva
