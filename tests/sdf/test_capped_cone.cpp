// Capped-cone distance: signs and values at known points, and the culled union field.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include "sdf/capped_cone.h"
#include "sdf/cone_field.h"

namespace sylva {
namespace {

const CappedCone kCone{{0, 0, 0}, {0, 2, 0}, 1.0f, 0.5f};

TEST(CappedCone, SignsAtKnownPoints) {
    EXPECT_LT(distance(kCone, {0, 1, 0}), 0.0f);        // on the axis
    EXPECT_LT(distance(kCone, {0.7f, 0.2f, 0}), 0.0f);  // near the wide base
    EXPECT_GT(distance(kCone, {0.7f, 1.9f, 0}), 0.0f);  // beside the narrow top
    EXPECT_GT(distance(kCone, {0, 3, 0}), 0.0f);        // above
    EXPECT_GT(distance(kCone, {0, -1, 0}), 0.0f);       // below
}

TEST(CappedCone, ExactDistancesOnTheAxisAndSides) {
    EXPECT_NEAR(distance(kCone, {0, 3, 0}), 1.0f, 1e-5);      // above the top cap
    EXPECT_NEAR(distance(kCone, {0, -0.5f, 0}), 0.5f, 1e-5);  // below the base
    // On the axis at mid-height the slanted side (radius 0.75 there) is nearer than the
    // caps: 0.75 * cos(slope), slope = atan(0.5 / 2).
    EXPECT_NEAR(distance(kCone, {0, 1, 0}), -0.75f * 2.0f / std::sqrt(4.25f), 1e-5);
    // A cylinder (ra == rb): distance to the side is radial.
    CappedCone cylinder{{0, 0, 0}, {0, 2, 0}, 0.5f, 0.5f};
    EXPECT_NEAR(distance(cylinder, {2, 1, 0}), 1.5f, 1e-5);
    EXPECT_NEAR(distance(cylinder, {0.25f, 1, 0}), -0.25f, 1e-5);
}

TEST(CappedCone, IsOneLipschitz) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-3, 3);
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 p{u(rng), u(rng), u(rng)}, q{u(rng), u(rng), u(rng)};
        EXPECT_LE(std::abs(distance(kCone, p) - distance(kCone, q)),
                  glm::length(p - q) * 1.0001f + 1e-5f);
    }
}

TEST(ConeField, MatchesTheBruteForceUnionBelowTheMargin) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 10), r(0.05f, 0.4f);
    std::vector<CappedCone> cones;
    for (int i = 0; i < 300; ++i) {
        glm::vec3 a{u(rng), u(rng), u(rng)};
        glm::vec3 b = a + glm::vec3(u(rng), u(rng), u(rng)) * 0.1f;
        cones.push_back({a, b, r(rng), r(rng)});
    }
    const float margin = 0.5f;
    ConeField field(cones, margin);
    for (int i = 0; i < 20000; ++i) {
        glm::vec3 p{u(rng) * 1.2f - 1, u(rng) * 1.2f - 1, u(rng) * 1.2f - 1};
        float exact = union_distance(cones, p), fast = field(p);
        if (exact < margin) {
            EXPECT_NEAR(fast, exact, 1e-5) << i;
        } else {  // a lower bound of the distance, never below the margin
            EXPECT_GE(fast, margin - 1e-5f) << i;
            EXPECT_LE(fast, exact + 1e-5f) << i;
        }
    }
}

// The meshers call the batch form; it must give the point-wise values bit for bit, or the
// meshes would change with the entry point.
TEST(ConeField, BatchEvaluationEqualsPointWise) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1, 3);
    const ConeField field({kCone, {{1, 0, 0}, {1, 1, 1}, 0.3f, 0.1f}}, 0.4f, 0.1f);
    std::vector<glm::vec3> points(1000);
    for (glm::vec3& p : points) p = {u(rng), u(rng), u(rng)};
    std::vector<float> values(points.size());
    field.evaluate(points, values);
    for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(values[i], field(points[i])) << i;
    field.evaluate({}, {});  // an empty batch is fine
}

}  // namespace
// F -> [F][F][F][F] draws thousands of copies of one segment; the field
// keeps one, so a sample visits one cone, not thousands.
TEST(ConeField, CoincidentCopiesAreMergedIntoOneCone) {
    std::vector<CappedCone> cones(4096, CappedCone{{0, 0, 0}, {0, 1, 0}, 0.05f, 0.04f});
    cones.push_back({{0, 1, 0}, {0, 0, 0}, 0.06f, 0.01f});  // the same segment, drawn back
    cones.push_back({{0, 1, 0}, {1, 1, 0}, 0.03f, 0.03f});  // a different one
    const std::vector<CappedCone> merged = merge_coincident_cones(cones, 1e-4f);
    ASSERT_EQ(merged.size(), 2u);
    EXPECT_FLOAT_EQ(merged[0].ra, 0.05f);
    EXPECT_FLOAT_EQ(merged[0].rb, 0.06f);
    EXPECT_EQ(merged[1].b, glm::vec3(1, 1, 0));
}

// ... and so do copies drawn with tiny turns (`F -> [+(0.01)F][-(0.01)F]...`): ends that
// differ by less than the tolerance, on either side of any rounding boundary.
TEST(ConeField, NearCoincidentCopiesAreMergedAndDistinctConesKept) {
    const float tolerance = 1e-3f;
    std::vector<CappedCone> cones;
    for (int i = 0; i < 2000; ++i) {
        const float t = tolerance * 0.4f * std::sin(float(i));  // within +-0.4 tolerance
        cones.push_back({{t, 0, -t}, {0.002f + t, 1, t}, 0.05f, 0.04f + 0.00001f * float(i % 5)});
    }
    cones.push_back({{0, 0, 0}, {0.002f + 2.5f * tolerance, 1, 0}, 0.05f, 0.04f});  // turned more
    const std::vector<CappedCone> merged = merge_coincident_cones(cones, tolerance);
    ASSERT_EQ(merged.size(), 2u);
    EXPECT_FLOAT_EQ(merged[0].rb, 0.04004f);
    EXPECT_EQ(merged[1].b, cones.back().b);
}

}  // namespace sylva
