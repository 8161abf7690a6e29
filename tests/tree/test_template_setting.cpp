// A template's #define constants as the command line and species files set them
// (tree/template_setting.h, tree/grammar_constants.h): held to the comment's range, whole
// numbers where the range is, the text around the value kept.
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "tree/grammar_constants.h"
#include "tree/growth.h"
#include "tree/parameters.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"
#include "tree/template_setting.h"

namespace {

using namespace sylva;

std::string error_of(TreeTemplate tree, const std::string& key, const std::string& value) {
    try {
        set_template_value(tree, key, value);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(GrammarConstants, ReadsNameValueRangeAndHelp) {
    const std::string grammar =
        "#define a  46      # [20, 75] main limbs, degrees\n"
        "#define n 5 # [2, 9] branches per whorl\n"
        "#define x (a*2)   # [0, 200] an expression\n"
        "#define y 3\n"
        "axiom: F(a)\n";
    const std::vector<GrammarDefine> d = grammar_defines(grammar);
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d[0].name, "a");
    EXPECT_EQ(d[0].value, 46.0);
    EXPECT_EQ(d[0].min, 20.0);
    EXPECT_EQ(d[0].max, 75.0);
    EXPECT_EQ(d[0].help, "main limbs, degrees");
    EXPECT_TRUE(d[1].integer);
    EXPECT_EQ(d[1].line, 2);
    EXPECT_FALSE(d[2].value);  // an expression has no number
    EXPECT_FALSE(d[3].min);    // no range comment
    std::string edited = grammar;
    ASSERT_TRUE(set_grammar_define(edited, "a", 60.5));
    EXPECT_EQ(edited.substr(0, edited.find('\n')),
              "#define a  60.5      # [20, 75] main limbs, degrees");
    EXPECT_EQ(edited.substr(edited.find('\n')), grammar.substr(grammar.find('\n')));
    EXPECT_FALSE(set_grammar_define(edited, "zz", 1));
}

// `--set a=60` on oak reaches the rules: the value is in the grammar and the tree changes.
TEST(TemplateSetting, SetsAGrammarConstantWithinItsRange) {
    const TreeTemplate oak = load_template("oak");
    TreeTemplate set = oak;
    set_template_value(set, "a", "60");
    EXPECT_EQ(find_grammar_define(set.grammar, "a")->value, 60.0);
    auto spread = [](const Skeleton& s) {  // how far the limbs reach sideways
        double sum = 0;
        for (const Segment& g : s.segments) sum += std::abs(g.b.x) + std::abs(g.b.z);
        return sum;
    };
    EXPECT_NE(spread(grow(set)), spread(grow(oak)));
    set_template_value(set, "a", 20.0);  // the range's ends are in it
    set_template_value(set, "a", "75");
    EXPECT_EQ(find_grammar_define(set.grammar, "a")->value, 75.0);

    std::string e = error_of(oak, "a", "90");
    EXPECT_NE(e.find("20 to 75"), std::string::npos) << e;
    e = error_of(oak, "a", "sixty");
    EXPECT_NE(e.find("expects a number"), std::string::npos) << e;
    EXPECT_NE(error_of(oak, "a", "nan"), "");
    // A whole-number range takes whole numbers, as the studio's slider does.
    const TreeTemplate willow = load_template("willow");
    e = error_of(willow, "n", "5.5");
    EXPECT_NE(e.find("whole numbers from 4 to 24"), std::string::npos) << e;
    EXPECT_EQ(error_of(willow, "n", "5"), "");
}

TEST(TemplateSetting, ParametersStillGoThroughTheRegistryAndUnknownKeysNameTheConstants) {
    TreeTemplate oak = load_template("oak");
    set_template_value(oak, "leaf_size", "0.3");
    EXPECT_EQ(*get_param(oak.params, "leaf_size"), 0.3);
    const std::string e = error_of(oak, "zz", "1");
    EXPECT_NE(e.find("unknown parameter 'zz'"), std::string::npos) << e;
    EXPECT_NE(e.find("#define constants: a, f, s, d"), std::string::npos) << e;
}

// A #define named like a parameter shadows it in the rules: setting the key sets both.
TEST(TemplateSetting, AConstantNamedLikeAParameterFollowsIt) {
    TreeTemplate t = load_template("oak");
    t.grammar = "#define leaf_size 0.2 # [0.05, 0.6] leaf\n" + t.grammar;
    set_template_value(t, "leaf_size", "0.4");
    EXPECT_EQ(*get_param(t.params, "leaf_size"), 0.4);
    EXPECT_EQ(find_grammar_define(t.grammar, "leaf_size")->value, 0.4);
}

}  // namespace
