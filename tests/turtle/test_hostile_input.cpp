// Hostile grammars: every one gets a clear error naming its line, or a defined
// result; none reaches undefined behaviour.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "derive_text.h"
#include "turtle/derivation.h"
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

// A 20,000-parameter module is a GrammarError at the parameter past the cap, on its line,
// not a bad_alloc.
TEST(HostileGrammar, AModuleWithTooManyParametersIsAGrammarErrorAtItsColumn) {
    std::string module = "A(1";
    for (int i = 1; i < 20'000; ++i) module += ",1";
    module += ")";
    try {
        parse_lsystem("# many\naxiom: " + module + "\n");
        FAIL() << "expected GrammarError";
    } catch (const GrammarError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.column(), 10 + 2 * kMaxModuleParameters) << e.what();
        EXPECT_NE(std::string(e.what()).find("parameters"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(parse_lsystem("axiom: A(1,2,3,4,5,6)\n"));
}

// F -> FF grows 2^n; its size is known exactly before deriving, and a word
// past the cap is refused before the first step (no 4M-module word is built first).
TEST(HostileGrammar, WordGrowthIsKnownBeforeDerivingAndRefusedEarly) {
    const LSystem ff = parse_lsystem("axiom: !(0.1)F\nF -> FF\n");
    const WordGrowth growth = word_growth(ff, 21);
    EXPECT_EQ(growth.low_modules, 2097153.0);
    EXPECT_EQ(growth.high_modules, growth.low_modules);
    EXPECT_EQ(growth.low_segments, 2097152.0);
    EXPECT_EQ(word_growth(ff, 1000).low_modules, 1e300);  // saturates, no overflow

    DeriveSettings settings;
    settings.steps = 1000;
    settings.max_modules = 1000;
    try {
        derive(ff, settings);
        FAIL() << "expected GrammarError";
    } catch (const GrammarError& e) {
        EXPECT_NE(std::string(e.what()).find("would grow"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("step 10"), std::string::npos) << e.what();
    }
    // A condition may stop growth: the low bound stays, the high bound grows.
    const LSystem guarded = parse_lsystem("axiom: A(0)\nA(x) : x < 3 -> A(x+1)A(x+1)\n");
    const WordGrowth g = word_growth(guarded, 10);
    EXPECT_EQ(g.low_modules, 1.0);
    EXPECT_EQ(g.high_modules, 1024.0);
    EXPECT_EQ(derive(guarded, {.steps = 10}).size(), 8u);
}

// Editors on Windows save UTF-8 with a byte order mark: the grammar reads as without it, and
// an error on the first line counts its column from after the mark.
TEST(HostileGrammar, AByteOrderMarkAtTheStartIsSkipped) {
    const std::string bom = "\xEF\xBB\xBF";
    const LSystem plain = parse_lsystem("axiom: F\nF -> FF\n");
    const LSystem marked = parse_lsystem(bom + "axiom: F\nF -> FF\n");
    EXPECT_EQ(marked.axiom.size(), plain.axiom.size());
    EXPECT_EQ(marked.rules.size(), plain.rules.size());
    EXPECT_EQ(derive_text(bom + "axiom: F\nF -> FF\n", 3).to_string(),
              derive_text("axiom: F\nF -> FF\n", 3).to_string());
    const GrammarError with = error_of(bom + "axiom: F(\n");
    const GrammarError without = error_of("axiom: F(\n");
    EXPECT_EQ(with.line(), 1);
    EXPECT_EQ(with.column(), without.column());
}

}  // namespace
}  // namespace sylva
