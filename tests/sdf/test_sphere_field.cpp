// The crown field: root smooth min properties and the culled field against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>
#include <random>
#include <vector>

#include "sdf/sphere_field.h"

namespace sylva {
namespace {

TEST(RootSmoothMin, LocalVersionEqualsTheSeedsWhereSpheresMeetAndMinFarther) {
    const float k = 0.1f;
    for (float a = -1; a <= 1; a += 0.01f) {
        EXPECT_FLOAT_EQ(local_root_smooth_min(a, a + 0.15f, k), root_smooth_min(a, a + 0.15f, k));
        EXPECT_FLOAT_EQ(local_root_smooth_min(a, a + 0.45f, k), a);
        // Never above min, never more than k/2 below it, and monotone in each argument.
        float s = local_root_smooth_min(a, 0.2f, k);
        EXPECT_LE(s, std::min(a, 0.2f) + 1e-6f);
        EXPECT_GE(s, std::min(a, 0.2f) - k / 2 - 1e-6f);
        EXPECT_LE(s, local_root_smooth_min(a + 0.01f, 0.2f, k) + 1e-6f);
    }
}

TEST(RootSmoothMin, BelowMinByAtMostHalfK) {
    const float k = 0.1f;
    for (float a = -1; a <= 1; a += 0.05f)
        for (float b = -1; b <= 1; b += 0.05f) {
            float s = root_smooth_min(a, b, k);
            EXPECT_LE(s, std::min(a, b) + 1e-6f);
            EXPECT_GE(s, std::min(a, b) - k / 2 - 1e-6f);
        }
    EXPECT_NEAR(root_smooth_min(0.3f, 0.3f, k), 0.3f - k / 2, 1e-6);
    EXPECT_FLOAT_EQ(root_smooth_min(0.2f, 0.7f, 0.0f), 0.2f);
}

std::vector<Ball> random_balls(std::mt19937& rng, int n) {
    std::uniform_real_distribution<float> u(0, 5), r(0.2f, 0.6f);
    std::vector<Ball> balls;
    for (int i = 0; i < n; ++i) balls.push_back({{u(rng), u(rng), u(rng)}, r(rng)});
    return balls;
}

TEST(SphereField, BlendsOnlyAddMaterialAndOnlyWhereSpheresMeet) {
    std::mt19937 rng(11);
    std::vector<Ball> balls = random_balls(rng, 30);
    const float k = 0.05f, margin = 0.5f;
    SphereField field(balls, k, margin);
    std::uniform_real_distribution<float> u(-1, 6);
    int alone = 0;
    for (int i = 0; i < 20000; ++i) {
        glm::vec3 p{u(rng), u(rng), u(rng)};
        std::vector<float> d;
        for (const Ball& b : balls) d.push_back(distance(b, p));
        std::sort(d.begin(), d.end());
        // The smooth union lies on or below the hard union (it only fills the creases), and
        // far away the value is still a lower bound of the distance.
        EXPECT_LE(field(p), d[0] + 1e-6f) << i;
        EXPECT_GE(field(p), std::min(d[0], margin) - 4 * k - 1e-6f) << i;
        // With one sphere well within the margin and no other near, there is nothing to
        // blend: the value is that sphere's exact distance.
        if (d[0] < margin - 4 * k && d[1] > d[0] + 4 * k) {
            EXPECT_NEAR(field(p), d[0], 1e-4) << i;
            ++alone;
        }
    }
    EXPECT_GT(alone, 50);
}

TEST(SphereField, IsOneLipschitzAndHardUnionWithoutBlend) {
    std::mt19937 rng(12);
    std::vector<Ball> balls = random_balls(rng, 50);
    SphereField smooth(balls, 0.1f, 1.0f), hard(balls, 0.0f, 1.0f);
    std::uniform_real_distribution<float> u(-1, 6);
    for (int i = 0; i < 5000; ++i) {
        glm::vec3 p{u(rng), u(rng), u(rng)}, q = p + glm::vec3(u(rng), u(rng), u(rng)) * 0.05f;
        // 1-Lipschitz below margin - 4k (the level the contract promises).
        if (smooth(p) < 0.6f && smooth(q) < 0.6f) {
            EXPECT_LE(std::abs(smooth(p) - smooth(q)), glm::length(p - q) * 1.001f + 1e-5f);
        }
        float exact = std::numeric_limits<float>::max();
        for (const Ball& b : balls) exact = std::min(exact, distance(b, p));
        if (exact < 1.0f) {
            EXPECT_NEAR(hard(p), exact, 1e-5);
        } else {  // beyond the margin: a lower bound of the distance, at least the margin
            EXPECT_GE(hard(p), 1.0f - 1e-6f);
            EXPECT_LE(hard(p), exact + 1e-5f);
        }
    }
}

// The meshers call the batch form; it must give the point-wise values bit for bit, or the
// meshes would change with the entry point.
TEST(SphereField, BatchEvaluationEqualsPointWise) {
    std::mt19937 rng(13);
    const std::vector<Ball> balls = random_balls(rng, 30);
    std::uniform_real_distribution<float> u(-1, 6);
    std::vector<glm::vec3> points(1000);
    for (glm::vec3& p : points) p = {u(rng), u(rng), u(rng)};
    for (const SphereField& field : {SphereField(balls, 0.1f, 1.0f),
                                     SphereField(balls, 0.5f, 1.0f, SphereBlend::PaskoSavchenko)}) {
        std::vector<float> values(points.size());
        field.evaluate(points, values);
        for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(values[i], field(points[i])) << i;
    }
}

// Nearest sphere first: the value is the same whatever order the spheres come in (the fold
// in the order listed made a crown's surface depend on the order of its tips).
TEST(SphereField, TheOrderOfTheSpheresDoesNotMatter) {
    std::mt19937 rng(17);
    std::vector<Ball> balls = random_balls(rng, 200);
    std::vector<Ball> shuffled = balls;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const SphereField field(balls, 0.1f, 0.7f), again(shuffled, 0.1f, 0.7f);
    std::uniform_real_distribution<float> u(-1, 6);
    int blended = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p{u(rng), u(rng), u(rng)};
        EXPECT_EQ(field(p), again(p)) << p.x << " " << p.y << " " << p.z;
        float first = 1e9f, second = 1e9f;  // where three or more spheres blend, order would show
        int close = 0;
        for (const Ball& b : balls) {
            const float d = distance(b, p);
            close += d < 0.4f ? 1 : 0;
            if (d < first)
                second = first, first = d;
            else
                second = std::min(second, d);
        }
        blended += close >= 3 && second - first < 0.4f ? 1 : 0;
    }
    EXPECT_GT(blended, 500);  // the points tried include many where order could matter
}

// A thousand spheres at one place must not fold the blend a thousand times, which would
// swell the union by about 4 k, past the box the crown is meshed in (an open crown). The
// fold stays within k/2 of the hard union, as for two spheres.
TEST(SphereField, ManySpheresAtOnePlaceSwellNoMoreThanTwo) {
    const float k = 0.1f;
    std::vector<Ball> balls(1000, Ball{{0, 0, 0}, 0.5f});
    for (std::size_t i = 0; i < balls.size(); ++i) balls[i].center.x = 1e-5f * float(i);
    const SphereField field(balls, k, 1.0f);
    const SphereField two({balls[0], balls[0]}, k, 1.0f);
    for (float x = 0.3f; x < 1.2f; x += 0.01f) {
        const glm::vec3 p{x, 0.2f, 0.1f};
        EXPECT_GE(field(p), distance(balls.back(), p) - k / 2 - 1e-5f) << x;
        EXPECT_NEAR(field(p), two(p), 0.02f) << x;
    }
}

TEST(SphereField, NearCoincidentBallsAreMergedWithinTheTolerance) {
    const float tolerance = 1e-3f;
    std::vector<Ball> balls;
    // 500 balls jittered within a third of the tolerance around a point on a cell boundary
    // of the hash (0.001 * 5), so rounding cannot split them.
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> jitter(-tolerance / 3, tolerance / 3);
    for (int i = 0; i < 500; ++i)
        balls.push_back(
            {{0.005f + jitter(rng), jitter(rng), jitter(rng)}, 0.2f + 0.001f * float(i % 7)});
    balls.push_back({{0.5f, 0, 0}, 0.3f});                    // another place
    balls.push_back({{0.005f + 3 * tolerance, 0, 0}, 0.2f});  // beyond the tolerance
    const std::vector<Ball> merged = merge_coincident_balls(balls, tolerance);
    ASSERT_EQ(merged.size(), 3u);
    EXPECT_EQ(merged[0].center, balls[0].center);  // the first one seen is kept
    EXPECT_FLOAT_EQ(merged[0].radius, 0.206f);     // with the largest radius
    EXPECT_EQ(merged[1].center, glm::vec3(0.5f, 0, 0));
    EXPECT_EQ(merge_coincident_balls(balls, 0.0f).size(), balls.size());
}

}  // namespace
}  // namespace sylva
