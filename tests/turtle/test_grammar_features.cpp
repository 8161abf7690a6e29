// Polygons traced by moves, colours, organs, the tropism vector, weights at the edges,
// #define rules, stochastic choice by noise over position, and the noise kinds.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <string>

#include "core/errors.h"
#include "core/noise.h"
#include "derive_text.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_growth.h"
#include "turtle/lsystem_params.h"
#include "turtle/lsystem_parser.h"
#include "turtle/turtle.h"

namespace sylva {
namespace {

Skeleton draw(const std::string& axiom, TurtleSettings settings = {}) {
    return interpret(derive_text("axiom: " + axiom + "\n", 0), settings);
}

void expect_near(const glm::vec3& a, const glm::vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-5);
    EXPECT_NEAR(a.y, b.y, 1e-5);
    EXPECT_NEAR(a.z, b.z, 1e-5);
}

TEST(Polygons, MovesTraceTheOutlineFromWhereTheBraceStood) {
    // A unit square: f up, turn, f left, turn, f down; the start is the first vertex.
    const Skeleton s = draw("F{f+(90)f+(90)f}");
    ASSERT_EQ(s.polygons.size(), 1u);
    ASSERT_EQ(s.polygons[0].size(), 4u);
    expect_near(s.polygons[0][0], {0, 1, 0});
    expect_near(s.polygons[0][1], {0, 2, 0});
    expect_near(s.polygons[0][2], {-1, 2, 0});
    expect_near(s.polygons[0][3], {-1, 1, 0});
    EXPECT_EQ(s.segments.size(), 1u);  // f draws nothing
}

TEST(Polygons, GAndLowercaseGMoveWithoutAVertexAndGDraws) {
    // g and G move without recording: the triangle's corners are the start and where f and
    // F ended.
    const Skeleton s = draw("{gf+(90)G+(90)F}");
    ASSERT_EQ(s.polygons.size(), 1u);
    ASSERT_EQ(s.polygons[0].size(), 3u);
    expect_near(s.polygons[0][0], {0, 0, 0});
    expect_near(s.polygons[0][1], {0, 2, 0});
    expect_near(s.polygons[0][2], {-1, 1, 0});
    EXPECT_EQ(s.segments.size(), 2u);  // G and F draw
    // Outside a polygon G moves like F and g like f.
    const Skeleton line = draw("GgG");
    ASSERT_EQ(line.segments.size(), 2u);
    expect_near(line.segments[1].b, {0, 3, 0});
}

TEST(Polygons, DotsKeepTheirOwnVerticesAndPolygonsNest) {
    // With dots only the dots count (as before); the inner polygon is its own.
    const Skeleton s = draw("{.f.+(90)f{f+(90)f+(90)f}.}");
    ASSERT_EQ(s.polygons.size(), 2u);
    EXPECT_EQ(s.polygons[0].size(), 4u);  // the inner one (a traced square) closes first
    expect_near(s.polygons[0][0], {-1, 1, 0});
    ASSERT_EQ(s.polygons[1].size(), 3u);  // the outer one's three dots
    expect_near(s.polygons[1][0], {0, 0, 0});
    expect_near(s.polygons[1][1], {0, 1, 0});
    expect_near(s.polygons[1][2], {-1, 0, 0});
    // A brace that does not close fails as before.
    EXPECT_THROW(draw("f}"), GrammarError);
}

TEST(Colours, IncrementDecrementSetAndPolygonsTakeTheirBracesColour) {
    const Skeleton s = draw("F'F''F;F'(7)F;(2)F;;;F[''{f+f+f}]{f+f+f}");
    ASSERT_EQ(s.segments.size(), 7u);
    const int expected[] = {0, 1, 3, 2, 7, 2, 0};  // ; stops at 0
    for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(s.segments[i].color, expected[i]) << i;
    EXPECT_EQ(s.polygon_colors, (std::vector<int>{2, 0}));
}

TEST(Organs, APlacedSurfaceHasTheTurtlesFrameSizeAndColour) {
    const Skeleton s = draw("F+(90)'(2)~apple(0.3)~cone(-1)");
    ASSERT_EQ(s.organs.size(), 2u);
    EXPECT_EQ(s.organs[0].surface, "apple");
    expect_near(s.organs[0].position, {0, 1, 0});
    expect_near(s.organs[0].heading, {-1, 0, 0});  // after +(90)
    EXPECT_FLOAT_EQ(s.organs[0].size, 0.3f);
    EXPECT_EQ(s.organs[0].color, 2);
    EXPECT_EQ(s.organs[1].surface, "cone");
    EXPECT_EQ(s.organs[1].size, 0.0f);  // no size: the surface's own
}

TEST(Organs, AWordWithoutTildeDrawsNothing) {
    const Skeleton s = interpret(derive_text("axiom: F apple\napple -> apple\n", 1), {});
    EXPECT_TRUE(s.organs.empty());
    EXPECT_EQ(s.segments.size(), 1u);
}

TEST(Tropism, TheVectorIsATemplateParameterAndZeroMeansDown) {
    TreeTemplate tree;
    tree.params.blocks.edit<LSystemParams>().tropism = 0.3;
    EXPECT_EQ(turtle_settings(tree).tropism, glm::dvec3(0, -1, 0));
    tree.params.tropism_vector.x = 1.0;
    EXPECT_EQ(turtle_settings(tree).tropism, glm::dvec3(1, 0, 0));
    // Bent towards +x: a vertical stem leans to +x.
    TurtleSettings settings = turtle_settings(tree);
    settings.elasticity = 0.3;
    const Skeleton s = draw("FFFF", settings);
    EXPECT_GT(s.segments.back().b.x, 0.5f);
}

TEST(Weights, HugeWeightsKeepTheirShares) {
    // 1e308 twice sums to infinity: both rules must still be chosen, about equally often.
    std::map<std::string, int> seen;
    for (std::uint64_t seed = 1; seed <= 400; ++seed)
        ++seen[derive_text("axiom: A\nA -> B : 1e308\nA -> C : 1e308\n", 1, seed).to_string()];
    EXPECT_GT(seen["B"], 150);
    EXPECT_GT(seen["C"], 150);
    // One huge weight and one small: the small one (almost) never.
    for (std::uint64_t seed = 1; seed <= 50; ++seed)
        EXPECT_EQ(derive_text("axiom: A\nA -> B : 1e308\nA -> C : 1\n", 1, seed).to_string(), "B");
}

TEST(Weights, AllZeroIsAnErrorAtTheFirstWeight) {
    try {
        derive_text("axiom: A\nA -> B : 0\nA -> C : 0*5\n", 1);
        FAIL() << "no error";
    } catch (const GrammarError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.column(), 10);
        EXPECT_NE(std::string(e.what()).find("all zero"), std::string::npos) << e.what();
    }
    // A zero weight among others is simply never chosen.
    for (std::uint64_t seed = 1; seed <= 30; ++seed)
        EXPECT_EQ(derive_text("axiom: A\nA -> B : 0\nA -> C : 2\n", 1, seed).to_string(), "C");
}

TEST(Defines, GivenTwiceIsAnErrorNamingBothLines) {
    try {
        parse_lsystem("#define a 1\naxiom: F(a)\n#define  a 2\n");
        FAIL() << "no error";
    } catch (const GrammarError& e) {
        EXPECT_EQ(e.line(), 3);
        EXPECT_EQ(e.column(), 10);
        EXPECT_NE(std::string(e.what()).find("first on line 1"), std::string::npos) << e.what();
    }
    // Overriding a supplied constant (a template parameter) still works: lint warns.
    const LSystem system = parse_lsystem("#define k 2\naxiom: F(k)\n", {{"k", 5.0}});
    Random random(1);
    EXPECT_EQ(axiom_word(system, random).args(0)[0], 2.0);
}

TEST(NoiseChoice, NeighboursChooseAlikeAndSharesHold) {
    // A row of 400 modules one meter apart along +Y: each picks B or C by noise at its place.
    const std::string grammar =
        "axiom: P(400)\nP(n) : n > 0 -> X f P(n-1)\nX -> B : 0.3, noise 0.1\nX -> C : 0.7, noise "
        "0.1\n";
    const Word word = derive_text(grammar, 401, 9);
    std::string picks;
    for (std::size_t i = 0; i < word.size(); ++i)
        if (word.symbol(i) == 'B' || word.symbol(i) == 'C') picks.push_back(word.symbol(i));
    ASSERT_EQ(picks.size(), 400u);
    const auto bs = std::count(picks.begin(), picks.end(), 'B');
    EXPECT_GT(bs, 60);  // 30% give or take what 4 noise cycles per 40 modules allow
    EXPECT_LT(bs, 180);
    int changes = 0;
    for (std::size_t i = 1; i < picks.size(); ++i) changes += picks[i] != picks[i - 1];
    // Random picks would change about 2 * 0.3 * 0.7 * 400 = 168 times; noise over a 10 m
    // wavelength changes a few times per cycle.
    EXPECT_LT(changes, 110);
    EXPECT_GT(changes, 2);
    // Deterministic, and another seed another field.
    EXPECT_EQ(derive_text(grammar, 401, 9).to_string(), word.to_string());
    EXPECT_NE(derive_text(grammar, 401, 10).to_string(), word.to_string());
}

TEST(NoiseChoice, TheOptionIsCheckedWhereItIsWritten) {
    for (const char* bad : {"axiom: A\nA -> B : 1, nose 2\n", "axiom: A\nA -> B : 1, noise\n",
                            "axiom: A\nA -> B : 1, noise -2\n"}) {
        try {
            parse_lsystem(bad);
            ADD_FAILURE() << bad;
        } catch (const GrammarError& e) {
            EXPECT_EQ(e.line(), 2) << bad;
            EXPECT_GE(e.column(), 11) << bad;
        }
    }
}

TEST(NoiseKinds, ExpressionsReadTheChosenKind) {
    const std::string grammar = "axiom: A(noise(0.3), noise(0.3, 1.7), noise_loop(2.5, 8))\n";
    for (NoiseKind kind : {NoiseKind::gradient, NoiseKind::value_linear, NoiseKind::value_cosine,
                           NoiseKind::value_cubic}) {
        DeriveSettings settings;
        settings.steps = 0;
        settings.seed = 77;
        settings.noise_kind = kind;
        const Word word = derive(parse_lsystem(grammar), settings);
        const NoiseField n = expression_noise(77, kind);
        EXPECT_DOUBLE_EQ(word.args(0)[0], n(0.3));
        EXPECT_DOUBLE_EQ(word.args(0)[1], n(0.3, 1.7));
        EXPECT_DOUBLE_EQ(word.args(0)[2], looping_noise(n, 0.0, 2.5, 8.0));
    }
    // Gradient is what noise() always was.
    EXPECT_DOUBLE_EQ(expression_noise(77, NoiseKind::gradient)(0.3), expression_noise(77)(0.3));
}

TEST(NoiseKinds, NoiseLoopRepeatsWithItsPeriod) {
    const Word word =
        derive_text("axiom: A(noise_loop(1.25, 6, 0.5), noise_loop(7.25, 6, 0.5))\n", 0, 3);
    EXPECT_NEAR(word.args(0)[0], word.args(0)[1], 1e-12);
    EXPECT_THROW(parse_lsystem("axiom: F\nF -> F(noise_loop(1))\n"), GrammarError);
}

}  // namespace
}  // namespace sylva
