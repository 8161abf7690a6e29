// Hostile grammars (issue 16): every one gets a clear error naming its line, or a defined
// result; none reaches undefined behaviour.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "derive_text.h"
#include "turtle/lsystem_parser.h"
#include "turtle/turtle.h"

namespace sylva {
namespace {

// The GrammarError `grammar` raises when parsed and derived one step.
GrammarError error_of(const std::string& grammar) {
    try {
        derive_text(grammar, 1);
    } catch (const GrammarError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for: " << grammar;
    return GrammarError("none");
}

TEST(HostileGrammar, EvaluationErrorsNameTheirLine) {
    EXPECT_EQ(error_of("#define z 1/0\naxiom: F\n").line(), 1);
    EXPECT_EQ(error_of("axiom: F\nF -> F : 1/0\n").line(), 2);
    const GrammarError axiom = error_of("# comment\naxiom: F(sqrt(-1))\n");
    EXPECT_EQ(axiom.line(), 2);
    EXPECT_NE(std::string(axiom.what()).find("F(sqrt(-1))"), std::string::npos) << axiom.what();
}

TEST(HostileGrammar, AnEmptyAxiomIsAnError) {
    const GrammarError e = error_of("axiom:\nF -> FF\n");
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(e.reason().find("empty"), std::string::npos);
}

TEST(HostileGrammar, ANulByteDoesNotCutTheMessage) {
    std::string grammar = "axiom: F\nF ";
    grammar.push_back('\0');
    grammar += " G\n";
    const GrammarError e = error_of(grammar);
    const std::string what = e.what();
    EXPECT_EQ(what.find('\0'), std::string::npos);
    EXPECT_NE(what.find("\\x00"), std::string::npos) << what;
    EXPECT_NE(what.find(" G"), std::string::npos) << "the rest of the line is shown: " << what;
}

TEST(HostileGrammar, ColourIndicesOutOfRangeAreClamped) {
    for (const char* axiom : {"'(2147483647)!(0.1)F'F", "'(1e300)!(0.1)F", "'(-5)!(0.1)F"}) {
        const Skeleton s = interpret(derive_text(std::string("axiom: ") + axiom + "\n", 0), {});
        ASSERT_FALSE(s.segments.empty()) << axiom;
        for (const Segment& seg : s.segments) {
            EXPECT_GE(seg.color, 0) << axiom;
            EXPECT_LE(seg.color, 1'000'000) << axiom;
        }
    }
}

}  // namespace
}  // namespace sylva
