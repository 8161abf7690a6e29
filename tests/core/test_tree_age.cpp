// core/tree_age.h on a hand-made skeleton: age 1 is the mature tree, the seedling is small
// but there, lengths and widths are continuous and only grow, parents stay valid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/tree_age.h"

namespace sylva {
namespace {

// A trunk of four unit segments going up, a branch of two from the second joint, leaves.
Skeleton sample_tree() {
    Skeleton s;
    auto add = [&](glm::vec3 a, glm::vec3 b, float ra, float rb, int parent, int depth) {
        Segment seg;
        seg.a = a, seg.b = b, seg.ra = ra, seg.rb = rb, seg.parent = parent, seg.depth = depth;
        s.segments.push_back(seg);
        return static_cast<int>(s.segments.size()) - 1;
    };
    int t = -1;
    for (int i = 0; i < 4; ++i)
        t = add({0, i, 0}, {0, i + 1, 0}, 0.4f - 0.08f * i, 0.32f - 0.08f * i, t, 0);
    int b = add({0, 2, 0}, {1, 2.5f, 0}, 0.1f, 0.08f, 1, 1);
    add({1, 2.5f, 0}, {2, 2.8f, 0}, 0.08f, 0.05f, b, 1);
    s.polygons.push_back({{2, 2.8f, 0}, {2.2f, 2.9f, 0}, {2.1f, 3.0f, 0}});
    return s;
}

// The longest root-to-tip path: along the branch.
const double kLongest = 2.0 + std::sqrt(1.25) + std::sqrt(1.09);

double total_length(const Skeleton& s) {
    double sum = 0.0;
    for (const Segment& seg : s.segments) sum += glm::distance(seg.a, seg.b);
    return sum;
}

float top(const Skeleton& s) {
    float y = 0.0f;
    for (const Segment& seg : s.segments) y = std::max({y, seg.a.y, seg.b.y});
    return y;
}

TEST(TreeAge, AgeOneIsTheMatureTree) {
    const Skeleton mature = sample_tree();
    const Skeleton same = skeleton_at_age(mature, 1.0);
    ASSERT_EQ(same.segments.size(), mature.segments.size());
    for (size_t i = 0; i < same.segments.size(); ++i) {
        EXPECT_EQ(same.segments[i].b, mature.segments[i].b);
        EXPECT_EQ(same.segments[i].ra, mature.segments[i].ra);
    }
    EXPECT_EQ(same.polygons.size(), 1u);
}

TEST(TreeAge, SeedlingIsSmallButThere) {
    const Skeleton seedling = skeleton_at_age(sample_tree(), 0.0);
    ASSERT_EQ(seedling.segments.size(), 1u);
    EXPECT_NEAR(top(seedling), kSeedlingFront * kLongest, 1e-5);
    // As thin as the mature tree's thinnest tip, not the trunk's 0.4.
    EXPECT_NEAR(seedling.segments[0].ra, 0.05f, 1e-6f);
    EXPECT_TRUE(seedling.polygons.empty());
}

TEST(TreeAge, ContinuousAndOnlyGrowing) {
    const Skeleton mature = sample_tree();
    Skeleton before = skeleton_at_age(mature, 0.0);
    for (int i = 1; i <= 1000; ++i) {
        const double age = i / 1000.0;
        const Skeleton now = skeleton_at_age(mature, age);
        // No popping: a thousandth of the age moves the total length by about a thousandth
        // of the longest path per growing branch tip (here at most 2 tips).
        const double grown = total_length(now) - total_length(before);
        EXPECT_GE(grown, -1e-5) << age;
        EXPECT_LE(grown, 2 * kLongest * 0.95 / 1000.0 + 1e-5) << age;
        EXPECT_GE(top(now), top(before) - 1e-6f) << age;
        EXPECT_GE(now.segments.size(), before.segments.size());
        for (size_t k = 0; k < before.segments.size(); ++k) {
            EXPECT_GE(now.segments[k].ra, before.segments[k].ra - 1e-6f) << age;
            EXPECT_LE(std::abs(now.segments[k].ra - before.segments[k].ra), 0.01f) << age;
        }
        for (size_t k = 0; k < now.segments.size(); ++k) {
            const int p = now.segments[k].parent;
            ASSERT_LT(p, static_cast<int>(k));
            if (p >= 0) {
                EXPECT_EQ(now.segments[static_cast<size_t>(p)].b, now.segments[k].a);
            }
        }
        before = now;
    }
}

TEST(TreeAge, GrownLimbsKeepTheirShapeWhileTheTrunkThickens) {
    const Skeleton mature = sample_tree();
    // The branch's path (2 + 1.12 + 1.04 = 4.16) is the longest; at 0.98 of it the trunk top
    // (4) is grown but the branch tip is not, so the trunk base is below its mature width.
    const Skeleton s = skeleton_at_age(mature, 0.98);
    ASSERT_EQ(s.segments.size(), mature.segments.size());
    EXPECT_EQ(s.segments[3].b, mature.segments[3].b);
    EXPECT_EQ(s.segments[3].rb, mature.segments[3].rb);  // the trunk's top carries nothing more
    EXPECT_LT(s.segments[0].ra, mature.segments[0].ra);
    EXPECT_EQ(s.polygons.size(), 0u);  // the leaf hangs at the branch tip, not reached yet
}

}  // namespace
}  // namespace sylva
