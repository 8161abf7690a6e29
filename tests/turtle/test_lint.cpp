// Grammar warnings (turtle/lint.h): each kind at its line and column, none for grammars that
// mean what they say.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "turtle/lint.h"

namespace sylva {
namespace {

void expect_warning(const std::string& grammar, int line, int column, const std::string& part,
                    const Constants& constants = {}) {
    const std::vector<LintWarning> w = lint_grammar(grammar, constants);
    ASSERT_EQ(w.size(), 1u) << grammar;
    EXPECT_EQ(w[0].line, line) << grammar;
    EXPECT_EQ(w[0].column, column) << grammar;
    EXPECT_NE(w[0].message.find(part), std::string::npos) << w[0].message;
}

TEST(Lint, ARuleWhosePredecessorNeverOccursWithThatArity) {
    // The oak's limbs all carry a length: F -> FFFFFFFF never applies.
    expect_warning("axiom: F(2)A(1)\nA(l) -> F(l)[+A(l*0.8)]A(l*0.9)\nF -> FFFFFFFF\n", 3, 1,
                   "has 'F' with 1 parameter");
    // A symbol no word ever holds.
    expect_warning("axiom: A\nA -> F[+A]A\n  B -> FF\n", 3, 3, "'B' at all");
    // Reachable only through a rule: fine.
    EXPECT_TRUE(lint_grammar("axiom: A\nA -> B\nB -> C\n").empty());
}

TEST(Lint, ARuleAnEarlierOneAlwaysWinsOver) {
    expect_warning("axiom: A\nA -> F\nA -> FF\n", 3, 1, "rule on line 2");
    expect_warning("axiom: A(1)\nA(x) : x > 1 -> F\nA(x) : x > 1 -> FF\n", 3, 1,
                   "the same condition");
    // Conditions that differ, contexts, or weights: no warning.
    EXPECT_TRUE(lint_grammar("axiom: A(1)\nA(x) : x > 1 -> F\nA(_x) -> FF\n").empty());
    EXPECT_TRUE(lint_grammar("axiom: BA\nB < A -> F\nA -> FF\n").empty());
    EXPECT_TRUE(lint_grammar("axiom: A\nA -> F : 1\nA -> FF : 2\n").empty());
}

TEST(Lint, ZeroWeightsAndUnreadNames) {
    expect_warning("axiom: A\nA -> F : 0\nA -> FF : 1\n", 2, 10, "never chosen");
    expect_warning("#define r 2\naxiom: F\n", 1, 9, "never read");
    expect_warning("axiom: A(1,2)\nA(x,y) -> F(x)A(x,y+0)\nA(_x,_y) -> B\n", 3, 1,
                   "rule on line 2");
    expect_warning("axiom: A(1,2)\nA(l,w) -> F(l)\n", 2, 5, "parameter 'w'");
    // A name starting with _ is bound on purpose.
    EXPECT_TRUE(lint_grammar("axiom: A(1,2)\nA(l,_w) -> F(l)\n").empty());
}

TEST(Lint, ADefineThatHidesAParameter) {
    expect_warning("#define tropism 0.5\naxiom: F(tropism)\n", 1, 9, "hides the parameter",
                   {{"tropism", 0.0}});
}

TEST(Lint, WordsThatDoNothingAndUnknownOrgans) {
    expect_warning("axiom: Apex\nApex -> Internode Apex\n", 2, 9, "'Internode' is a word module");
    const std::vector<LintWarning> w =
        lint_grammar("axiom: F ~apple ~pear\n", {}, {"apple", "cone"});
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].column, 17);
    EXPECT_NE(w[0].message.find("unknown organ '~pear' (known: apple, cone)"), std::string::npos)
        << w[0].message;
}

TEST(Lint, ParseErrorsStillThrow) {
    EXPECT_THROW(lint_grammar("axiom: F(\n"), GrammarError);
}

}  // namespace
}  // namespace sylva
