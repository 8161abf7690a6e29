// Adding a growth method is one folder and one registration line: the "dummy" method of
// dummy/ is linked into this test and into `sylva-with-dummy` (the CLI built from app/ with
// it), and nothing else names it. Its parameters then appear in `sylva --help`, are taken by
// --set and template files, land in skeleton.json and show as the studio's controls (enabled
// for a dummy tree, greyed with the reason for another).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.h"
#include "tests/growth_method/dummy/dummy_growth.h"
#include "tests/helpers.h"
#include "tree/growth.h"
#include "tree/parameter_help.h"
#include "tree/parameters.h"
#include "tree/template_file.h"
#ifdef SYLVA_HAS_STUDIO
#include "ui/state/template_controls.h"
#endif

namespace sylva {
namespace {

namespace fs = std::filesystem;

constexpr const char* kKeys[] = {"dummy_height", "dummy_stems", "dummy_fan"};

// Exit code and output of the CLI built with the dummy method.
test::CommandResult run(const std::string& args) {
    return test::run_command(std::string(SYLVA_WITH_DUMMY) + " " + args);
}

TreeTemplate dummy_tree() {
    return parse_template_file(
        "name = \"stems\"\ngrowth = \"dummy\"\n[params]\ndummy_stems = 3\ndummy_fan = true\n",
        "stems.toml");
}

TEST(GrowthMethod, ItsParametersAreInTheHelp) {
    const auto [code, help] = run("--help");
    EXPECT_EQ(code, 0);
    EXPECT_NE(help.find(parameter_help()), std::string::npos);
    EXPECT_NE(help.find("dummy"), std::string::npos);
    for (const char* key : kKeys) EXPECT_NE(help.find(key), std::string::npos) << key;
}

TEST(GrowthMethod, TemplateFilesAndSetReadItsParameters) {
    const TreeTemplate tree = dummy_tree();
    EXPECT_EQ(*get_param(tree.params, "dummy_stems"), 3.0);
    EXPECT_EQ(tree.params.blocks.get<dummy::DummyParams>().fan, true);
    EXPECT_EQ(grow(tree).segments.size(), 3u);
    TreeTemplate taller = tree;
    set_param(taller.params, "dummy_height", "5");
    EXPECT_FLOAT_EQ(grow(taller).segments[0].b.y, 5.0f);
    EXPECT_THROW(set_param(taller.params, "dummy_stems", "10"), InputError);  // range 1-9
    // Written and read back; no grammar, since the method reads none.
    const std::string text = template_file_text(taller);
    EXPECT_NE(text.find("dummy_height = 5.0"), std::string::npos) << text;
    EXPECT_EQ(text.find("grammar"), std::string::npos) << text;
    EXPECT_EQ(*get_param(parse_template_file(text, "back.toml").params, "dummy_height"), 5.0);
}

using GrowthMethodCli = test::TempFolderTest;

TEST_F(GrowthMethodCli, GrowsItAndWritesItsParameters) {
    const fs::path& dir = dir_;
    const fs::path file = dir / "stems.toml";
    std::ofstream(file) << template_file_text(dummy_tree());
    const auto [code, out] = run("skeleton -t " + file.string() + " --set dummy_height=4 -o " +
                                 (dir / "skeleton.json").string());
    EXPECT_EQ(code, 0) << out;
    EXPECT_NE(out.find("3 segments"), std::string::npos) << out;
    const std::string doc = test::read_file(dir / "skeleton.json");
    EXPECT_NE(doc.find("\"dummy_height\": 4.0"), std::string::npos) << doc.substr(0, 400);
    const auto [export_code, exported] =
        run("export -t " + file.string() + " -o " + (dir / "stems.glb").string());
    EXPECT_EQ(export_code, 0) << exported;
}

#ifdef SYLVA_HAS_STUDIO
TEST(GrowthMethod, ItsParametersAreTheStudiosControls) {
    auto row_of = [](const std::vector<studio::ParameterRow>& rows, std::string_view key) {
        return std::find_if(rows.begin(), rows.end(),
                            [&](const studio::ParameterRow& r) { return r.info->key == key; });
    };
    const std::vector<studio::ParameterRow> rows = studio::parameter_rows(dummy_tree());
    for (const char* key : kKeys) {
        const auto row = row_of(rows, key);
        ASSERT_NE(row, rows.end()) << key;
        EXPECT_EQ(row->unread, "") << key;
    }
    // Grouped as its table says: dummy_height with the shape, the rest with the method.
    EXPECT_EQ(row_of(rows, "dummy_height")->info->group, ParamGroup::Shape);
    EXPECT_EQ(row_of(rows, "dummy_fan")->info->group, ParamGroup::GrowthMethod);
    EXPECT_NE(row_of(rows, "generations")->unread, "");  // the L-system's
    TreeTemplate lsystem;
    lsystem.grammar = "axiom: F\n";
    const std::vector<studio::ParameterRow> other = studio::parameter_rows(lsystem);
    for (const char* key : kKeys) {
        const auto row = row_of(other, key);
        ASSERT_NE(row, other.end()) << key;
        EXPECT_NE(row->unread.find("dummy"), std::string::npos) << row->unread;
    }
}
#endif

}  // namespace
}  // namespace sylva
