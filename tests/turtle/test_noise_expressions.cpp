// noise() and fbm() in rule expressions: seeded by the tree's seed, deterministic, equal to
// core/noise.h's values, and clear errors (line and column) for a wrong number of arguments,
// a bad octave count, or noise where no seed is known (#define, weights).
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "core/noise.h"
#include "derive_text.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_parser.h"

namespace sylva {
namespace {

TEST(NoiseExpressions, MatchCoreNoiseSeededByTheTreeSeed) {
    const std::string grammar =
        "axiom: A(noise(0.3), noise(0.3, 1.7), noise(0.3, 1.7, 2.9), fbm(3, 0.3), "
        "fbm(3, 0.3, 1.7), fbm(5, 0.3, 1.7, 2.9))\n";
    const Word word = derive_text(grammar, 0, 77);
    const GradientNoise n = expression_noise(77);
    const FbmSettings three{3, 1.0, 0.5, 2.0}, five{5, 1.0, 0.5, 2.0};
    const auto a = word.args(0);
    ASSERT_EQ(a.size(), 6u);
    EXPECT_DOUBLE_EQ(a[0], n(0.3));
    EXPECT_DOUBLE_EQ(a[1], n(0.3, 1.7));
    EXPECT_DOUBLE_EQ(a[2], n(0.3, 1.7, 2.9));
    EXPECT_DOUBLE_EQ(a[3], fbm(n, 0.3, three));
    EXPECT_DOUBLE_EQ(a[4], fbm(n, 0.3, 1.7, three));
    EXPECT_DOUBLE_EQ(a[5], fbm(n, 0.3, 1.7, 2.9, five));
    for (const double v : a) EXPECT_NE(v, 0.0);
}

TEST(NoiseExpressions, SameSeedSameWordOtherSeedOtherWord) {
    // A branch whose angle follows noise along its length, driven by a rule parameter.
    const std::string grammar = "axiom: A(0)\nA(s) : s < 12 -> F +(40*noise(s*0.37)) A(s+1)\n";
    EXPECT_EQ(derive_text(grammar, 12, 5).to_string(), derive_text(grammar, 12, 5).to_string());
    EXPECT_NE(derive_text(grammar, 12, 5).to_string(), derive_text(grammar, 12, 6).to_string());
}

TEST(NoiseExpressions, CoherentAlongARuleParameter) {
    // Neighbouring parameters give neighbouring values: no jump larger than the slope allows.
    const Word word =
        derive_text("axiom: A(0)\nA(s) : s < 200 -> B(noise(s*0.05)) A(s+1)\n", 200, 3);
    double previous = word.args(0)[0];
    for (size_t i = 1; i + 1 < word.size(); ++i) {
        const double v = word.args(i)[0];
        EXPECT_LT(std::abs(v - previous), 0.25) << i;
        previous = v;
    }
}

TEST(NoiseExpressions, WrongArityNamesLineAndColumn) {
    struct Case {
        const char* grammar;
        int column;
        const char* fragment;
    };
    const Case cases[] = {
        {"axiom: F\nF -> F(noise())\n", 8, "noise takes 1 to 3 arguments (x[, y[, z]]), not 0"},
        {"axiom: F\nF -> F(noise(1,2,3,4))\n", 8, "noise takes 1 to 3 arguments"},
        {"axiom: F\nF -> F(1 + fbm(4))\n", 12, "fbm takes 2 to 4 arguments (octaves, x[, y[, z]])"},
        {"axiom: F\nF -> F(fbm(1,2,3,4,5))\n", 8, "not 5"},
        {"axiom: F\nF -> F(fbm(0, 1))\n", 12,
         "number of octaves, a whole number from 1 to 16, not 0"},
        {"axiom: F\nF -> F(fbm(2.5, 1))\n", 12, "not 2.5"},
        {"axiom: F\nF -> F(fbm(17, 1, 2))\n", 12, "not 17"},
    };
    for (const Case& c : cases) {
        try {
            parse_lsystem(c.grammar);
            ADD_FAILURE() << "no error for: " << c.grammar;
        } catch (const GrammarError& e) {
            EXPECT_EQ(e.line(), 2) << c.grammar;
            EXPECT_EQ(e.column(), c.column) << c.grammar << " -> " << e.what();
            EXPECT_NE(std::string(e.what()).find(c.fragment), std::string::npos)
                << c.grammar << " -> " << e.what();
        }
    }
}

TEST(NoiseExpressions, ComputedOctaveCountIsCheckedAtDerivation) {
    try {
        derive_text("axiom: A(0)\nA(x) -> B(fbm(x, 1))\n", 1);
        FAIL() << "expected a GrammarError";
    } catch (const GrammarError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_NE(std::string(e.what()).find("number of octaves"), std::string::npos) << e.what();
    }
}

TEST(NoiseExpressions, NotAvailableWithoutASeed) {
    for (const char* grammar :
         {"#define k noise(0.5)\naxiom: F(k)\n", "axiom: F\nF -> FF : noise(0.5) + 1\n"}) {
        try {
            parse_lsystem(grammar);
            ADD_FAILURE() << "no error for: " << grammar;
        } catch (const GrammarError& e) {
            EXPECT_GT(e.line(), 0);
            EXPECT_GT(e.column(), 0);
            EXPECT_NE(std::string(e.what()).find("depend on the tree's seed"), std::string::npos)
                << e.what();
        }
    }
}

}  // namespace
}  // namespace sylva
