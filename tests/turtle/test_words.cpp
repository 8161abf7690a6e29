// Word modules (docs/grammar.md, "Words"): ABOP's plant of Fig. 1.26 and L-Py style grammars
// derive the same modules, step by step, as an independent reference: a plain string
// rewriter over whitespace-separated tokens that shares no code with the parser. Drawn
// geometry is checked against a plane turtle written out here.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

#include "core/errors.h"
#include "derive_text.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_parser.h"
#include "turtle/turtle.h"

namespace sylva {
namespace {

// ABOP Fig. 1.26 (n = 5, delta = 18 degrees), as ABOP writes it: modules apart.
const char* const kAbopPlant = R"(axiom: plant
plant -> internode + [plant + flower] - - // [- - leaf] internode [+ + leaf] - [plant flower] + + plant flower
internode -> F seg [// & & leaf] [// ^ ^ leaf] F seg
seg -> seg F seg
leaf -> [' { + f - f f - f + | + f - f f - f } ]
flower -> [& & & pedicel ' / wedge //// wedge //// wedge //// wedge //// wedge]
pedicel -> F F
wedge -> [^ F] [{ & & & & - f + f | - f + f }]
)";

// The same plant as ABOP prints it: runs of turtle letters without spaces ("FF", "+f-ff-f+").
const char* const kAbopPlantAsPrinted = R"(axiom: plant
plant -> internode+[plant+flower]--//[--leaf]internode[++leaf]-[plant flower]++plant flower
internode -> F seg[//&&leaf][//^^leaf]F seg
seg -> seg F seg
leaf -> ['{+f-ff-f+|+f-ff-f}]
flower -> [&&&pedicel'/wedge////wedge////wedge////wedge////wedge]
pedicel -> FF
wedge -> [^F][{&&&&-f+f|-f+f}]
)";

// The reference: rules as token lists; a token is a run of letters, digits and '_' that
// starts with a letter, or any other single character. Every token without a rule stays.
struct Reference {
    std::vector<std::string> axiom;
    std::map<std::string, std::vector<std::string>> rules;
};

// With `words` false every character is a token (a grammar of single characters).
std::vector<std::string> tokens(const std::string& text, bool words = true) {
    static const std::regex word_token(R"([A-Za-z][A-Za-z0-9_]*|\S)"), char_token(R"(\S)");
    const std::regex& token = words ? word_token : char_token;
    std::vector<std::string> out;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), token);
         it != std::sregex_iterator(); ++it)
        out.push_back(it->str());
    return out;
}

Reference reference(const std::string& grammar, bool words = true) {
    Reference r;
    std::size_t start = 0;
    while (start < grammar.size()) {
        std::size_t end = grammar.find('\n', start);
        if (end == std::string::npos) end = grammar.size();
        const std::string line = grammar.substr(start, end - start);
        start = end + 1;
        if (line.rfind("axiom:", 0) == 0) {
            r.axiom = tokens(line.substr(6), words);
        } else if (const std::size_t arrow = line.find("->"); arrow != std::string::npos) {
            const std::vector<std::string> pred = tokens(line.substr(0, arrow), words);
            EXPECT_EQ(pred.size(), 1u) << line;
            r.rules[pred[0]] = tokens(line.substr(arrow + 2), words);
        }
    }
    return r;
}

std::vector<std::string> rewrite(const Reference& r, const std::vector<std::string>& word) {
    std::vector<std::string> next;
    for (const std::string& t : word) {
        const auto rule = r.rules.find(t);
        if (rule == r.rules.end())
            next.push_back(t);
        else
            next.insert(next.end(), rule->second.begin(), rule->second.end());
    }
    return next;
}

std::vector<std::string> names_of(const Word& word) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < word.size(); ++i)
        out.emplace_back(word.symbol_name(word.symbol(i)));
    return out;
}

std::size_t count(const std::vector<std::string>& word, const std::string& token) {
    return static_cast<std::size_t>(std::count(word.begin(), word.end(), token));
}

// Steps 0..steps of `grammar` against the reference: the same modules in the same order.
void expect_matches_reference(const std::string& grammar, int steps) {
    const Reference r = reference(grammar);
    std::vector<std::string> expected = r.axiom;
    for (int n = 0; n <= steps; ++n) {
        const Word word = derive_text(grammar, n);
        ASSERT_EQ(word.size(), expected.size()) << "step " << n << " of\n" << grammar;
        EXPECT_EQ(names_of(word), expected) << "step " << n;
        expected = rewrite(r, expected);
    }
}

TEST(Words, AbopPlantMatchesTheReferenceStepByStep) {
    expect_matches_reference(kAbopPlant, 5);
    // The reference's own counts at ABOP's n = 5.
    const Reference r = reference(kAbopPlant);
    std::vector<std::string> word = r.axiom;
    for (int n = 0; n < 5; ++n) word = rewrite(r, word);
    EXPECT_EQ(word.size(), derive_text(kAbopPlant, 5).size());
    EXPECT_GT(count(word, "flower"), 100u);
}

TEST(Words, AbopPlantAsPrintedDerivesTheSameModules) {
    for (int n = 0; n <= 5; ++n)
        EXPECT_EQ(names_of(derive_text(kAbopPlantAsPrinted, n)),
                  names_of(derive_text(kAbopPlant, n)))
            << "step " << n;
}

TEST(Words, LPyStyleGrammarsMatchTheReference) {
    // Apices, internodes and leaves with names, as L-Py writes them.
    expect_matches_reference(R"(axiom: Apex
Apex -> Internode [ + Leaf ] [ - Apex ] Internode Apex
Internode -> Internode F
Leaf -> [ { . - f . + f . + f . } ]
)",
                             7);
    // Words that share letters with each other and with turtle letters, and digits.
    expect_matches_reference(R"(axiom: A1 B_2 Flower
A1 -> A1 B_2 [ + Flower ]
B_2 -> F B_2 f
Flower -> Fl Fl
Fl -> F
)",
                             6);
    // A word predecessor among single-character ones: each keeps its meaning.
    expect_matches_reference(R"(axiom: X
X -> F [ + X ] F [ - X ] + X Bud
Bud -> Bud Bloom
F -> F F
)",
                             5);
}

TEST(Words, ALecturesZeroLSystemGivesItsTableOfWords) {
    // A 0L system as a lecture on L-systems tabulates it (generation 1 is the axiom; its
    // rule for a, printed a -> cdc, is a -> cbc by the table). The table's later rows
    // carry slips of the pen (a k too many); from the sixth on the words are the rules'.
    const char* const grammar = "axiom: a\na -> cbc\nb -> dad\nc -> k\nd -> a\nk -> k\n";
    const char* const table[] = {"a",
                                 "cbc",
                                 "kdadk",
                                 "kacbcak",
                                 "kcbckdadkcbck",
                                 "kkdadkkacbcakkdadkk",
                                 "kkacbcakkcbckdadkcbckkacbcakk"};
    for (int n = 0; n < 7; ++n) EXPECT_EQ(derive_text(grammar, n).to_string(), table[n]) << n + 1;
}

TEST(Words, AbopBushAsPrintedTracesItsLeaves) {
    // ABOP Fig. 1.25 as printed, with its leaf traced by f (no dots): every leaf a flat
    // hexagon, one per { in the word.
    const std::string grammar = R"(axiom: A
A -> [&FL!A]/////'[&FL!A]///////'[&FL!A]
F -> S ///// F
S -> F L
L -> ['''^^{-f+f+f-|-f+f+f}]
)";
    const Reference r = reference(grammar, false);
    std::vector<std::string> word = r.axiom;
    for (int n = 0; n < 4; ++n) word = rewrite(r, word);
    EXPECT_EQ(names_of(derive_text(grammar, 4)), word);
    TurtleSettings settings;
    settings.width_model = WidthModel::Explicit;
    const Skeleton drawn = interpret(derive_text(grammar, 4), settings);
    EXPECT_EQ(drawn.segments.size(), count(word, "F"));
    ASSERT_EQ(drawn.polygons.size(), count(word, "{"));
    ASSERT_GT(drawn.polygons.size(), 10u);
    for (const auto& polygon : drawn.polygons) {
        ASSERT_EQ(polygon.size(), 6u);
        const glm::vec3 normal =
            glm::normalize(glm::cross(polygon[1] - polygon[0], polygon[2] - polygon[0]));
        for (const glm::vec3& v : polygon)
            EXPECT_NEAR(glm::dot(v - polygon[0], normal), 0.0f, 1e-5f);
    }
}

TEST(Words, SingleCharacterGrammarsKeepTheirMeaning) {
    // Without a word predecessor every character is a module, as before: "FF" is F F,
    // "AB" is A B and letters run together.
    const Word w = derive_text("axiom: AB\nA -> FFA\nB -> Fx\n", 2);
    EXPECT_EQ(w.to_string(), "FFFFAFx");
    EXPECT_EQ(w.size(), 7u);
    EXPECT_EQ(w.names(), nullptr);
}

TEST(Words, WordsCarryParametersAndContexts) {
    const Word w = derive_text(R"(axiom: Apex(3) Leaf
Apex(n) : n > 0 -> Internode(n) [ + Apex(n - 1) ] Apex(n - 1)
Apex(n) < Leaf : n > 1 -> Leaf Leaf
)",
                               2);
    EXPECT_EQ(w.to_string(),
              "Internode(3)[+Internode(2)[+Apex(1)]Apex(1)]Internode(2)[+Apex(1)]Apex(1)Leaf Leaf "
              "Leaf");
    // A word's text reads back to the same modules.
    const Word again = derive_text("axiom: " + w.to_string() + "\nApex(n) -> Apex(n)\n", 0);
    EXPECT_EQ(again.to_string(), w.to_string());
    EXPECT_EQ(again.size(), w.size());
}

TEST(Words, RulesMatchWordAndArity) {
    const Word w = derive_text("axiom: seg seg(1)\nseg -> A\nseg(x) -> B\n", 1);
    EXPECT_EQ(w.to_string(), "A B");  // apart: "AB" would read as a word here
}

TEST(Words, TooManyWordsIsAnErrorAtItsColumn) {
    std::string grammar = "axiom: start\nstart ->";
    for (int i = 0; i <= kMaxWords; ++i) grammar += " w" + std::to_string(i);
    grammar += "\n";
    try {
        parse_lsystem(grammar);
        FAIL() << "no error";
    } catch (const GrammarError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_NE(std::string(e.what()).find("at most 128 different words"), std::string::npos)
            << e.what();
    }
}

// A plane turtle for a word of F, f, + and - (ABOP's turn formulas, degrees), giving every
// point a move reaches; the heading starts up (+Y) as Sylva's does.
std::vector<glm::dvec2> plane_walk(const std::string& moves, double degrees) {
    glm::dvec2 p(0.0), h(0.0, 1.0);
    std::vector<glm::dvec2> out{p};
    const double a = degrees * std::numbers::pi / 180.0;
    for (char c : moves) {
        if (c == 'f' || c == 'F') out.push_back(p += h);
        // + turns left: from +Y towards -X (L = (-1, 0, 0) at the start).
        if (c == '+')
            h = {h.x * std::cos(a) - h.y * std::sin(a), h.x * std::sin(a) + h.y * std::cos(a)};
        if (c == '-')
            h = {h.x * std::cos(a) + h.y * std::sin(a), -h.x * std::sin(a) + h.y * std::cos(a)};
        if (c == '|') h = -h;
    }
    return out;
}

TEST(Words, AbopLeafIsTheTracedOutline) {
    // ABOP Fig. 1.26's leaf: { } traced by f moves, the last move back at the start.
    TurtleSettings settings;
    settings.turn_angle = 18.0;
    const Word leaf =
        derive_text("axiom: leaf\nleaf -> [' { + f - f f - f + | + f - f f - f } ]\n", 1);
    const Skeleton drawn = interpret(leaf, settings);
    ASSERT_EQ(drawn.polygons.size(), 1u);
    EXPECT_EQ(drawn.polygon_colors, std::vector<int>{1});  // the ' before {
    const std::vector<glm::dvec2> walk = plane_walk("+f-ff-f+|+f-ff-f", 18.0);
    ASSERT_EQ(walk.size(), 9u);
    EXPECT_LT(glm::length(walk.back() - walk.front()), 1e-9);  // back where it started
    const std::vector<glm::vec3>& polygon = drawn.polygons[0];
    ASSERT_EQ(polygon.size(), 8u);  // the closing vertex is the first
    for (std::size_t k = 0; k < 8; ++k) {
        EXPECT_NEAR(polygon[k].x, walk[k].x, 1e-5) << k;
        EXPECT_NEAR(polygon[k].y, walk[k].y, 1e-5) << k;
        EXPECT_NEAR(polygon[k].z, 0.0, 1e-5) << k;
    }
}

TEST(Words, AbopPlantDrawsAsTheReferenceCounts) {
    // Every F a segment, every { } (the leaves and wedges already drawn) a polygon, one
    // colour up.
    TurtleSettings settings;
    settings.turn_angle = settings.pitch_angle = settings.roll_angle = 18.0;
    settings.width_model = WidthModel::Explicit;
    const Reference r = reference(kAbopPlant);
    std::vector<std::string> word = r.axiom;
    for (int n = 0; n < 5; ++n) word = rewrite(r, word);
    const Skeleton drawn = interpret(derive_text(kAbopPlant, 5), settings);
    EXPECT_EQ(drawn.segments.size(), count(word, "F"));
    EXPECT_EQ(drawn.polygons.size(), count(word, "{"));
    EXPECT_GT(count(word, "{"), 100u);
    ASSERT_EQ(drawn.polygon_colors.size(), drawn.polygons.size());
    for (std::size_t k = 0; k < drawn.polygons.size(); ++k) {
        EXPECT_EQ(drawn.polygon_colors[k], 1);
        EXPECT_GE(drawn.polygons[k].size(), 4u);
    }
    // The stem's internodes are whole: every step keeps the plant upright (its first
    // segments go straight up).
    EXPECT_NEAR(drawn.segments[0].b.x, 0.0f, 1e-6);
    EXPECT_GT(drawn.segments[0].b.y, 0.0f);
}

TEST(Words, AbopFlowerHasFivePetalsEvenlyAroundItsPedicel) {
    // ABOP Fig. 1.26's flower: after the pedicel the turtle rolls 72 degrees (////, four
    // times 18) between five wedges, so the petals stand at 72 degrees around the pedicel.
    TurtleSettings settings;
    settings.turn_angle = settings.pitch_angle = settings.roll_angle = 18.0;
    const Word flower = derive_text(R"(axiom: flower
flower -> [& & & pedicel ' / wedge //// wedge //// wedge //// wedge //// wedge]
pedicel -> F F
wedge -> [^ F] [{ & & & & - f + f | - f + f }]
)",
                                    2);
    const Skeleton drawn = interpret(flower, settings);
    ASSERT_EQ(drawn.polygons.size(), 5u);
    ASSERT_EQ(drawn.segments.size(), 2u + 5u);   // the pedicel and a stamen per wedge
    const glm::vec3 base = drawn.segments[1].b;  // the pedicel's end
    const glm::vec3 axis = glm::normalize(drawn.segments[1].b - drawn.segments[0].a);
    std::vector<glm::vec3> out;
    for (const auto& polygon : drawn.polygons) {
        glm::vec3 centre(0.0f);
        for (const glm::vec3& v : polygon) centre += v;
        centre /= static_cast<float>(polygon.size());
        const glm::vec3 d = centre - base;
        out.push_back(glm::normalize(d - glm::dot(d, axis) * axis));
        EXPECT_EQ(polygon.size(), 4u);  // a wedge: a thin rhombus
    }
    for (std::size_t k = 0; k < 5; ++k) {
        const float cosine = glm::dot(out[k], out[(k + 1) % 5]);
        EXPECT_NEAR(std::acos(std::clamp(cosine, -1.0f, 1.0f)) * 180.0 / std::numbers::pi, 72.0,
                    1e-3)
            << k;
    }
}

}  // namespace
}  // namespace sylva
