// L-system parsing and derivation: known words from ABOP and Heuer 2022, errors that name
// their place, and the size cap.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "derive_text.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_parser.h"

namespace sylva {
namespace {

TEST(LSystem, AbopFigure124aWordLength) {
    Word w = derive_text("axiom: F\nF -> F[+F]F[-F]F\n", 5);
    EXPECT_EQ(w.size(), 7811u);
    EXPECT_EQ(w.count('F'), 3125u);
}

TEST(LSystem, IdentityForSymbolsWithoutRule) {
    Word w = derive_text("axiom: AXB\nA -> AA\n", 3);
    EXPECT_EQ(w.to_string(), "AAAAAAAAXB");
}

TEST(LSystem, ParametricSequenceOfAbopFigure132) {
    const std::string grammar = R"(
axiom: B(2)A(4,4)
A(x,y) : y <= 3 -> A(x*2,x+y)
A(x,y) : y > 3 -> B(x)A(x/y,0)
B(x) : x < 1 -> C
B(x) : x >= 1 -> B(x-1)
)";
    const char* expected[] = {"B(2)A(4,4)", "B(1)B(4)A(1,0)", "B(0)B(3)A(2,1)", "CB(2)A(4,3)",
                              "CB(1)A(8,7)"};
    for (int steps = 0; steps < 5; ++steps)
        EXPECT_EQ(derive_text(grammar, steps).to_string(), expected[steps]) << steps;
}

TEST(LSystem, RulesMatchOnArity) {
    Word w = derive_text("axiom: A A(1) A(1,2)\nA(x) -> B(x+1)\n", 1);
    EXPECT_EQ(w.to_string(), "AB(2)A(1,2)");
}

TEST(LSystem, DefinesAndFunctions) {
    Word w = derive_text(
        "#define r 0.5  # a comment\naxiom: A(8)\n"
        "A(x) -> A(max(x*r, 3) + sqrt(4) - abs(-1) + floor(0.7))\n",
        2);
    EXPECT_EQ(w.to_string(), "A(4)");  // 8 -> max(4,3)+2-1+0 = 5 -> max(2.5,3)+2-1+0 = 4
}

TEST(LSystem, SuppliedConstantsAndDefinesOverridingThem) {
    DeriveSettings d;
    d.steps = 0;
    EXPECT_EQ(derive(parse_lsystem("axiom: F(k*2)\n", {{"k", 1.5}}), d).to_string(), "F(3)");
    EXPECT_EQ(derive(parse_lsystem("#define k 4\naxiom: F(k)\n", {{"k", 1.5}}), d).to_string(),
              "F(4)");
}

TEST(LSystem, AcropetalSignalWithLeftContext) {
    const std::string grammar = "axiom: baaaaaaaa\nb < a -> b\nb -> a\n";
    EXPECT_EQ(derive_text(grammar, 1).to_string(), "abaaaaaaa");
    EXPECT_EQ(derive_text(grammar, 4).to_string(), "aaaabaaaa");
}

TEST(LSystem, Seed001RuleFormat) {
    // Heuer 2022, pattern 1: "#axiom" then the axiom, "#rules" then rules, identity rules too.
    const std::string grammar =
        "#axiom\nA\n#rules\nA -> ^^FB\nB -> C+++C---\nC -> [^F&B]\nF -> F\n+ -> +\n- -> -\n"
        "[ -> [\n] -> ]\n^ -> ^\n& -> &\n";
    Word w = derive_text(grammar, 5);
    // Heuer's (2022) word (5.2) after 5 steps, symbol for symbol. (Its text says 54 symbols;
    // the printed word has 55.)
    EXPECT_EQ(w.to_string(), "^^F[^F&[^F&B]+++[^F&B]---]+++[^F&[^F&B]+++[^F&B]---]---");
}

TEST(LSystem, StochasticWordIsReproducibleAndSeedDependent) {
    const std::string grammar = "axiom: F\nF -> F[+F]F : 1\nF -> F[-F]F : 1\nF -> FF : 1\n";
    Word a = derive_text(grammar, 5, 7), b = derive_text(grammar, 5, 7),
         c = derive_text(grammar, 5, 8);
    EXPECT_EQ(a.to_string(), b.to_string());
    EXPECT_NE(a.to_string(), c.to_string());
}

TEST(LSystemErrors, RuleWithoutArrowNamesLineAndColumn) {
    try {
        parse_lsystem("axiom: F\nF -> FF\n  F = FF\n");
        FAIL() << "expected a GrammarError";
    } catch (const GrammarError& e) {
        EXPECT_EQ(e.line(), 3);
        EXPECT_EQ(e.column(), 3);
        EXPECT_NE(std::string(e.what()).find("->"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("  F = FF\n      ^"), std::string::npos) << e.what();
    }
}

TEST(LSystemErrors, EachBrokenGrammarIsAClearError) {
    struct Case {
        const char* grammar;
        int line;
        const char* fragment;
    };
    const Case cases[] = {
        {"axiom: F[+F\n", 1, "never closed"},
        {"axiom: F\nF -> F]F\n", 2, "without a matching"},
        {"axiom: F\nF -> F(foo(1))\n", 2, "unknown function"},
        {"axiom: F\nF -> F(sin(1,2))\n", 2, "takes 1 argument"},
        {"axiom: F\nF -> F(x)\n", 2, "unknown name 'x'"},
        {"axiom: F\nF -> F(1+)\n", 2, "ends too early"},
        {"axiom: F(1\n", 1, "never closed"},
        {"F -> FF\n", 0, "no axiom"},
        {"axiom: F\nA(x,x) -> F\n", 2, "named twice"},
    };
    for (const Case& c : cases) {
        try {
            parse_lsystem(c.grammar);
            ADD_FAILURE() << "no error for: " << c.grammar;
        } catch (const GrammarError& e) {
            EXPECT_EQ(e.line(), c.line) << c.grammar;
            EXPECT_NE(std::string(e.what()).find(c.fragment), std::string::npos)
                << c.grammar << " -> " << e.what();
        }
    }
}

TEST(LSystemErrors, DivisionByZeroInAConditionNamesTheRule) {
    try {
        derive_text("axiom: A(0)\nA(x) : 1/x > 0 -> B\n", 1);
        FAIL() << "expected a GrammarError";
    } catch (const GrammarError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_NE(std::string(e.what()).find("division by zero"), std::string::npos);
    }
}

TEST(LSystemErrors, ExplosiveGrammarStopsAtTheCapNamingStepAndSize) {
    DeriveSettings settings;
    settings.steps = 40;
    settings.max_modules = 50'000;
    try {
        derive(parse_lsystem("axiom: F\nF -> FFFFFFFFFF\n"), settings);
        FAIL() << "expected a GrammarError";
    } catch (const GrammarError& e) {
        std::string message = e.what();
        EXPECT_NE(message.find("step 5"), std::string::npos) << message;  // 10^5 > 50000
        EXPECT_NE(message.find("50000"), std::string::npos) << message;
    }
}

TEST(LSystemErrors, DeeplyNestedExpressionIsRejectedNotACrash) {
    std::string deep =
        "axiom: F(" + std::string(100000, '(') + "1" + std::string(100000, ')') + ")";
    EXPECT_THROW(parse_lsystem(deep), GrammarError);
    std::string minus = "axiom: F(" + std::string(100000, '-') + "1)";
    EXPECT_THROW(parse_lsystem(minus), GrammarError);
}

}  // namespace
}  // namespace sylva
