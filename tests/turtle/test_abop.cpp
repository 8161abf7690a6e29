// Grammars from ABOP (Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of Plants),
// checked against independent computations rather than against Sylva's own output.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "derive_text.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_parser.h"
#include "turtle/turtle.h"

namespace sylva {
namespace {

// Word length after n steps of a D0L system by Parikh vectors: count symbols, never build
// the word. rules maps a symbol to its successor; other symbols map to themselves.
std::size_t parikh_length(const std::string& axiom, const std::map<char, std::string>& rules,
                          int steps) {
    std::map<char, std::size_t> counts;
    for (char c : axiom) ++counts[c];
    for (int i = 0; i < steps; ++i) {
        std::map<char, std::size_t> next;
        for (auto [symbol, n] : counts) {
            auto rule = rules.find(symbol);
            if (rule == rules.end())
                next[symbol] += n;
            else
                for (char c : rule->second) next[c] += n;
        }
        counts = next;
    }
    std::size_t total = 0;
    for (auto [symbol, n] : counts) total += n;
    return total;
}

TEST(Abop, Figure124WordLengths) {
    struct Figure {
        const char* name;
        std::string axiom;
        std::map<char, std::string> rules;
        int steps;
    };
    const Figure figures[] = {
        {"a", "F", {{'F', "F[+F]F[-F]F"}}, 5},
        {"b", "F", {{'F', "F[+F]F[-F][F]"}}, 5},
        {"c", "F", {{'F', "FF-[-F+F+F]+[+F-F-F]"}}, 4},
        {"d", "X", {{'X', "F[+X]F[-X]+X"}, {'F', "FF"}}, 7},
        {"e", "X", {{'X', "F[+X][-X]FX"}, {'F', "FF"}}, 7},
        {"f", "X", {{'X', "F-[[X]+X]+F[+FX]-X"}, {'F', "FF"}}, 5},
    };
    for (const Figure& f : figures) {
        std::string grammar = "axiom: " + f.axiom + "\n";
        for (auto& [symbol, successor] : f.rules)
            grammar += std::string(1, symbol) + " -> " + successor + "\n";
        EXPECT_EQ(derive_text(grammar, f.steps).size(), parikh_length(f.axiom, f.rules, f.steps))
            << "figure 1.24" << f.name;
    }
    EXPECT_EQ(parikh_length("F", {{'F', "F[+F]F[-F]F"}}, 5), 7811u);  // the figure's own count
}

// A plain reference rewriter for context-sensitive, non-parametric L-systems, written
// straight from ABOP's definition, to compare the engine against.
struct ContextRule {
    char left, pred, right;  // 0 = no context
    std::string successor;
};

std::string reference_step(const std::string& w, const std::vector<ContextRule>& rules,
                           const std::string& ignore) {
    auto ignored = [&](char c) { return ignore.find(c) != std::string::npos; };
    auto left_of = [&](size_t i) -> char {
        int depth = 0;
        for (size_t k = i; k-- > 0;) {
            char c = w[k];
            if (c == ']')
                ++depth;
            else if (c == '[') {
                if (depth > 0) --depth;
            } else if (depth == 0 && !ignored(c))
                return c;
        }
        return 0;
    };
    auto right_of = [&](size_t i) -> char {
        int depth = 0;
        for (size_t k = i + 1; k < w.size(); ++k) {
            char c = w[k];
            if (c == '[')
                ++depth;
            else if (c == ']') {
                if (depth == 0) return 0;
                --depth;
            } else if (depth == 0 && !ignored(c))
                return c;
        }
        return 0;
    };
    std::string out;
    for (size_t i = 0; i < w.size(); ++i) {
        const ContextRule* hit = nullptr;
        for (const ContextRule& r : rules) {
            if (r.pred != w[i]) continue;
            if (r.left && left_of(i) != r.left) continue;
            if (r.right && right_of(i) != r.right) continue;
            hit = &r;
            break;
        }
        out += hit ? hit->successor : std::string(1, w[i]);
    }
    return out;
}

TEST(Abop, Figure131aContextSensitiveWithIgnoredSymbols) {
    const std::string grammar = R"(#ignore +-F
axiom: F1F1F1
0 < 0 > 0 -> 0
0 < 0 > 1 -> 1[+F1F1]
0 < 1 > 0 -> 1
0 < 1 > 1 -> 1
1 < 0 > 0 -> 0
1 < 0 > 1 -> 1F1
1 < 1 > 0 -> 1
1 < 1 > 1 -> 0
* < + > * -> -
* < - > * -> +
)";
    const std::vector<ContextRule> rules = {{'0', '0', '0', "0"}, {'0', '0', '1', "1[+F1F1]"},
                                            {'0', '1', '0', "1"}, {'0', '1', '1', "1"},
                                            {'1', '0', '0', "0"}, {'1', '0', '1', "1F1"},
                                            {'1', '1', '0', "1"}, {'1', '1', '1', "0"},
                                            {0, '+', 0, "-"},     {0, '-', 0, "+"}};
    std::string reference = "F1F1F1";
    for (int step = 1; step <= 30; ++step) reference = reference_step(reference, rules, "+-F");
    Word w = derive_text(grammar, 30);
    EXPECT_EQ(w.to_string(), reference);
    EXPECT_GT(w.count('['), 10u);  // it really branched
}

TEST(Abop, HondaMonopodialTreeHasTwoToTheNApices) {
    const std::string grammar = R"(#define r1 0.9
#define r2 0.6
#define a0 45
#define a2 45
#define d 137.5
#define wr 0.707
axiom: A(1,10)
A(l,w) : * -> !(w)F(l)[&(a0)B(l*r2,w*wr)]/(d)A(l*r1,w*wr)
B(l,w) : * -> !(w)F(l)[-(a2)$C(l*r2,w*wr)]C(l*r1,w*wr)
C(l,w) : * -> !(w)F(l)[+(a2)$B(l*r2,w*wr)]B(l*r1,w*wr)
)";
    for (int n = 0; n <= 10; ++n) {
        Word w = derive_text(grammar, n);
        EXPECT_EQ(w.count('A') + w.count('B') + w.count('C'), std::size_t{1} << n) << n;
    }
    // The first internode keeps its length; the main axis shortens by r1 per step.
    Word w = derive_text(grammar, 2);
    EXPECT_EQ(w.to_string().rfind("!(10)F(1)", 0), 0u) << w.to_string();
    Skeleton tree = interpret(w, {});
    EXPECT_EQ(tree.segments.size(), 3u);
}

TEST(Abop, StochasticRuleFrequenciesPassChiSquare) {
    // 6000 A's rewritten once by rules weighted 1:2:3.
    const std::string grammar =
        "axiom: " + std::string(6000, 'A') + "\nA -> X : 1\nA -> Y : 2\nA -> Z : 3\n";
    Word w = derive_text(grammar, 1, 12345);
    const double observed[3] = {double(w.count('X')), double(w.count('Y')), double(w.count('Z'))};
    const double expected[3] = {1000, 2000, 3000};
    double chi2 = 0;
    for (int i = 0; i < 3; ++i)
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    EXPECT_LT(chi2, 13.82);  // 2 degrees of freedom, p = 0.001
    EXPECT_EQ(observed[0] + observed[1] + observed[2], 6000);
}

TEST(Abop, ConditionsGuardStochasticRules) {
    // Only guarded rules that hold compete: x > 5 never holds, so every A becomes Y.
    Word w = derive_text("axiom: A(1)A(2)A(3)\nA(x) : x > 5 -> X : 1\nA(x) -> Y : 1\n", 1);
    EXPECT_EQ(w.to_string(), "YYY");
}

}  // namespace
}  // namespace sylva
