// Template files: every built-in parses, errors name file, line and key, and saving then
// loading gives the same template.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "tree/parameters.h"
#include "tree/template_file.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

std::string error_of(const std::string& text) {
    try {
        parse_template_file(text, "trees/x.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(TemplateFile, ErrorsNameFileLineAndKey) {
    const std::string head = "name = \"x\"\ngrammar = \"axiom: F\"\n";
    std::string e = error_of(head + "[params]\ngenerations = 99\n");
    EXPECT_NE(e.find("trees/x.toml:4"), std::string::npos) << e;
    EXPECT_NE(e.find("generations"), std::string::npos) << e;
    EXPECT_NE(e.find("0 to 15"), std::string::npos) << e;

    e = error_of(head + "[params]\nno_such = 1\n");
    EXPECT_NE(e.find("trees/x.toml:4"), std::string::npos) << e;
    EXPECT_NE(e.find("no_such"), std::string::npos) << e;

    e = error_of(head + "[params]\nleaf_shape = \"maple\"\n");
    EXPECT_NE(e.find("leaf_shape"), std::string::npos) << e;
    EXPECT_NE(e.find("round, oak, needle, frond"), std::string::npos) << e;

    e = error_of(head + "turtle = \"logo\"\n");
    EXPECT_NE(e.find(":3"), std::string::npos) << e;
    EXPECT_NE(e.find("abop, lptg"), std::string::npos) << e;

    e = error_of("name = \"x\"\n");
    EXPECT_NE(e.find("grammar"), std::string::npos) << e;

    e = error_of(head + "[colors]\ntrunk = [1, 2]\n");
    EXPECT_NE(e.find("trees/x.toml:4"), std::string::npos) << e;
    EXPECT_NE(e.find("trunk"), std::string::npos) << e;

    e = error_of("name = \"x\"\ngrammar = \"axiom: F\n");  // broken TOML
    EXPECT_NE(e.find("trees/x.toml:2"), std::string::npos) << e;

    e = error_of(head + "colour = 3\n");
    EXPECT_NE(e.find("colour"), std::string::npos) << e;
}

TEST(TemplateFile, SaveThenLoadGivesTheSameTemplate) {
    for (const TreeTemplate* t : builtin_templates()) {
        SCOPED_TRACE(t->name);
        TreeTemplate back = parse_template_file(template_file_text(*t), "saved.toml");
        EXPECT_EQ(back.name, t->name);
        EXPECT_EQ(back.description, t->description);
        EXPECT_EQ(back.grammar, t->grammar) << t->name;
        EXPECT_EQ(back.mode, t->mode);
        EXPECT_EQ(back.width_model, t->width_model);
        for (const ParamInfo& info : param_infos())
            EXPECT_EQ(*get_param(back.params, info.key), *get_param(t->params, info.key))
                << t->name << " " << info.key;
        EXPECT_EQ(back.params.seed, t->params.seed);
        EXPECT_EQ(back.colors.trunk, t->colors.trunk);
        EXPECT_EQ(back.colors.leaves, t->colors.leaves);
    }
}

// Found by fuzz/fuzz_template: a grammar without a final newline read back with one, and a
// control character (from an escape such as "\u0001") was written where TOML forbids it.
TEST(TemplateFile, SaveThenLoadKeepsTheGrammarByteForByte) {
    for (const std::string grammar :
         {"axiom: F", "axiom: F\n", "axiom: F'", "axiom: F''", "axiom: F\"", "axiom: F\nF -> '''F",
          "axiom: F\nF -> '''F\n", "axiom: F\x01", "axiom: F\r\nF -> F\\F\r", "\naxiom: F\t\x7f",
          ""}) {
        SCOPED_TRACE(grammar);
        TreeTemplate tree;
        tree.name = "x";
        tree.grammar = grammar;
        const std::string text = template_file_text(tree);
        TreeTemplate back;
        ASSERT_NO_THROW(back = parse_template_file(text, "saved.toml")) << text;
        EXPECT_EQ(back.grammar, grammar) << text;
    }
}

TEST(TemplateFile, TheLibraryHasTheSpeciesTheIssueAsksFor) {
    for (const char* name : {"oak", "spruce", "fir", "palm", "honda", "ternary", "bush", "birch",
                             "willow", "pine", "baobab", "cypress", "seed_spruce"})
        EXPECT_NO_THROW(load_template(name)) << name;
    EXPECT_GE(builtin_templates().size(), 16u);
    EXPECT_EQ(default_template().name, "oak");
    for (const TreeTemplate* t : builtin_templates())
        EXPECT_FALSE(t->description.empty()) << t->name;
}

}  // namespace
}  // namespace sylva
