// Turtle variation: bend, jitter, width and tropism variation. Zero amounts draw
// the word exactly as before whatever the seed; otherwise the same seed gives the same
// skeleton, bending is a smooth curve of the same length, jitter stays within its range,
// and widths stay continuous along a branch.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "turtle/derivation.h"
#include "turtle/lsystem_parser.h"
#include "turtle/turtle.h"

namespace sylva {
namespace {

Skeleton draw(const std::string& axiom, const TurtleSettings& settings) {
    DeriveSettings d;
    d.steps = 0;
    return interpret(derive(parse_lsystem("axiom: " + axiom), d), settings);
}

bool same(const Skeleton& a, const Skeleton& b) {
    if (a.segments.size() != b.segments.size()) return false;
    for (size_t i = 0; i < a.segments.size(); ++i) {
        const Segment &x = a.segments[i], &y = b.segments[i];
        if (x.a != y.a || x.b != y.b || x.ra != y.ra || x.rb != y.rb || x.parent != y.parent)
            return false;
    }
    return true;
}

double degrees_between(const glm::vec3& u, const glm::vec3& v) {
    const double c = glm::dot(glm::normalize(u), glm::normalize(v));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

const char* const kTree = "F(2)[+(30)F(1.5)F][-(30)F(1.5)F]F(2)[&(40)F(1.5)]F";

TEST(TurtleVariation, ZeroAmountsIgnoreTheSeed) {
    TurtleSettings a, b;
    a.elasticity = b.elasticity = 0.3;
    b.seed = 12345;
    EXPECT_TRUE(same(draw(kTree, a), draw(kTree, b)));
}

TEST(TurtleVariation, EachAmountIsSeededAndDeterministic) {
    for (int which = 0; which < 4; ++which) {
        TurtleSettings s;
        s.elasticity = 0.3;
        (which == 0   ? s.bend
         : which == 1 ? s.jitter
         : which == 2 ? s.width_variation
                      : s.tropism_variation) = 0.5;
        if (which == 0) s.bend = 40.0;
        TurtleSettings other = s;
        other.seed = 2;
        TurtleSettings plain;
        plain.elasticity = 0.3;
        EXPECT_TRUE(same(draw(kTree, s), draw(kTree, s))) << which;
        EXPECT_FALSE(same(draw(kTree, s), draw(kTree, other))) << which;
        EXPECT_FALSE(same(draw(kTree, s), draw(kTree, plain))) << which;
    }
}

TEST(TurtleVariation, BendIsASmoothCurveOfTheSameLength) {
    TurtleSettings s;
    s.bend = 30.0;           // degrees per meter at noise 1
    s.bend_frequency = 0.5;  // pieces of 1/8 cycle = 0.25 m
    s.seed = 7;
    const Skeleton curve = draw("F(10)", s);
    ASSERT_EQ(curve.segments.size(), 32u);  // 10 m / 0.25 m = 40, capped at 32 pieces per F
    double length = 0.0;
    for (size_t i = 0; i < curve.segments.size(); ++i) {
        const Segment& seg = curve.segments[i];
        length += glm::distance(seg.a, seg.b);
        if (i == 0) continue;
        const Segment& before = curve.segments[i - 1];
        EXPECT_EQ(seg.parent, static_cast<int>(i - 1));
        EXPECT_EQ(seg.a, before.b);
        // Each joint turns by at most bend * piece length on each of two axes.
        EXPECT_LE(degrees_between(before.b - before.a, seg.b - seg.a),
                  std::sqrt(2.0) * 30.0 * (10.0 / 32.0) + 1e-3);
    }
    EXPECT_NEAR(length, 10.0, 1e-4);
    const glm::vec3 end = curve.segments.back().b;
    EXPECT_GT(std::hypot(end.x, end.z), 0.1) << "the branch left the straight line";
}

TEST(TurtleVariation, BendKeepsTheTaperOfEachF) {
    TurtleSettings plain;
    plain.initial_width = 0.2;
    TurtleSettings bent = plain;
    bent.bend = 20.0;
    const Skeleton a = draw("F(2)F(2)", plain), b = draw("F(2)F(2)", bent);
    EXPECT_FLOAT_EQ(b.segments.front().ra, a.segments.front().ra);
    EXPECT_NEAR(b.segments.back().rb, a.segments.back().rb, 1e-6);
    for (size_t i = 1; i < b.segments.size(); ++i)
        EXPECT_NEAR(b.segments[i].ra, b.segments[i - 1].rb, 1e-6);
}

TEST(TurtleVariation, JitterStaysWithinItsRange) {
    TurtleSettings s;
    s.jitter = 0.3;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        s.seed = seed;
        const Skeleton t = draw("F(1)[+(40)F(1)][-(40)F(1)]", s);
        ASSERT_EQ(t.segments.size(), 3u);
        for (const Segment& seg : t.segments) {
            const double length = glm::distance(seg.a, seg.b);
            EXPECT_GE(length, 0.7 - 1e-5);
            EXPECT_LE(length, 1.3 + 1e-5);
        }
        for (int i : {1, 2}) {
            const double angle = degrees_between(t.segments[0].b - t.segments[0].a,
                                                 t.segments[i].b - t.segments[i].a);
            EXPECT_GE(angle, 40.0 * 0.7 - 1e-3);
            EXPECT_LE(angle, 40.0 * 1.3 + 1e-3);
            EXPECT_EQ(t.segments[i].a, t.segments[0].b);
        }
    }
}

TEST(TurtleVariation, WidthVariationIsContinuousAlongABranch) {
    TurtleSettings s;
    s.width_model = WidthModel::Explicit;
    s.initial_width = 0.2;
    s.width_variation = 0.5;
    s.bend_frequency = 1.0;
    const Skeleton t = draw("FFFFFFFFFF", s);
    bool varied = false;
    for (size_t i = 0; i < t.segments.size(); ++i) {
        EXPECT_GE(t.segments[i].ra, 0.1f * 0.5f - 1e-6f);
        EXPECT_LE(t.segments[i].ra, 0.1f * 1.5f + 1e-6f);
        varied = varied || std::abs(t.segments[i].ra - 0.1f) > 0.005f;
        if (i > 0) {
            EXPECT_FLOAT_EQ(t.segments[i].ra, t.segments[i - 1].rb);
        }
    }
    EXPECT_TRUE(varied);
}

}  // namespace
}  // namespace sylva
