// The studio's basics as state, without a window: the cost estimate and the confirmation an
// expensive edit asks for, reset to the template, colours that need no new tree, the
// unsaved-changes mark, recent files, and saving a template that keeps its comments.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "tests/ui/wait_for_generations.h"
#include "tree/cost.h"
#include "tree/template_file.h"
#include "tree/template_library.h"
#include "turtle/lsystem_params.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {
namespace {

using Clock = std::chrono::steady_clock;

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct TempDir {
    std::filesystem::path path;
    TempDir() {
        path = std::filesystem::temp_directory_path() /
               ("sylva_basics_" + std::to_string(Clock::now().time_since_epoch().count()));
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
};

// Generations 12 on the oak: the estimate is made before anything runs, the job is held
// back with the estimate in words, and "run anyway" starts it (cancelled here at once).
TEST(StudioBasics, AnExpensiveEditAsksFirst) {
    StudioState state;
    load_template_into(state, load_template("oak"));
    ASSERT_TRUE(wait_for_generations(state));
    const auto shown = state.tree;
    EXPECT_TRUE(state.cost_warning.empty());
    const double cheap_modules = state.estimate.modules;
    EXPECT_GT(cheap_modules, 0);

    state.tree_template.params.blocks.edit<LSystemParams>().generations = 12;
    start_generation(state);
    EXPECT_FALSE(state.job.has_value());  // nothing started
    EXPECT_FALSE(state.cost_warning.empty());
    EXPECT_NE(state.cost_warning.find("modules"), std::string::npos);
    EXPECT_GT(state.estimate.modules, 20 * cheap_modules);
    EXPECT_GT(state.estimate.segments, state.ask_segments);
    EXPECT_EQ(state.tree, shown);  // the tree on screen stays

    state.run_costly = true;
    start_generation(state);
    ASSERT_TRUE(state.job.has_value());
    EXPECT_TRUE(state.cost_warning.empty());
    EXPECT_EQ(state.job_estimate.modules, state.estimate.modules);
    cancel_generation(state);
    EXPECT_FALSE(state.job.has_value());
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_EQ(state.tree, shown);
}

// No built-in template asks before its own default tree is made.
TEST(StudioBasics, NoTemplateAsksForItsDefault) {
    const StudioState state;
    for (const TreeTemplate* t : builtin_templates())
        EXPECT_FALSE(asks_first(state, estimate_cost(*t)))
            << t->name << ": " << cost_text(estimate_cost(*t));
}

TEST(StudioBasics, ResetGoesBackToTheTemplateAndUndoBringsTheEditBack) {
    StudioState state;
    const TreeTemplate birch = load_template("birch");
    load_template_into(state, birch);
    state.tree_template.params.leaf_size = 0.9;
    state.tree_template.colors.leaves = {1.0f, 0.0f, 0.0f};
    commit_edit(state);
    EXPECT_TRUE(unsaved_changes(state));
    reset_to_template(state);
    EXPECT_TRUE(same_template(state.tree_template, state.original));
    EXPECT_EQ(state.tree_template.params.leaf_size, birch.params.leaf_size);
    EXPECT_FALSE(unsaved_changes(state));
    undo(state);
    EXPECT_EQ(state.tree_template.params.leaf_size, 0.9);
    cancel_generations(state);
    ASSERT_TRUE(wait_for_generations(state));
}

// A colour is no new tree: the shown tree takes it at once, and it is an unsaved change.
TEST(StudioBasics, ColoursRecolourTheShownTreeWithoutANewOne) {
    StudioState state;
    TreeTemplate t = load_template("oak");
    t.params.blocks.edit<LSystemParams>().generations = 3;
    t.params.trunk_resolution = 24;
    t.params.crown_resolution = 16;
    load_template_into(state, t);
    ASSERT_TRUE(wait_for_generations(state));
    const auto shown = state.tree;
    PartColors colors = state.tree_template.colors;
    colors.trunk = {0.9f, 0.1f, 0.1f};
    set_colors(state, colors);
    EXPECT_EQ(state.shown_template.colors.trunk, colors.trunk);
    EXPECT_FALSE(edit_pending(state));
    EXPECT_TRUE(unsaved_changes(state));
    EXPECT_TRUE(commit_edit(state));  // undoable
    EXPECT_EQ(state.tree, shown);
    undo(state);
    EXPECT_EQ(state.tree_template.colors.trunk, t.colors.trunk);
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_EQ(state.tree, shown);                                  // still no new tree
    EXPECT_EQ(state.shown_template.colors.trunk, t.colors.trunk);  // but the old colour
}

// Saving the oak keeps the built-in file's comments (its header, the grammar's), writes 0.8
// as 0.8, and reads back to the same template.
TEST(StudioBasics, SavingKeepsCommentsAndShortNumbers) {
    TempDir dir;
    StudioState state;
    load_template_into(state, load_template("oak"));
    cancel_generations(state);
    state.tree_template.params.leaf_size = 0.8;
    state.tree_template.colors.crown = {0.1f, 0.7f, 0.2f};
    state.template_path = (dir.path / "my_oak.toml").string();
    save_template_to_file(state);
    ASSERT_FALSE(state.file_failed) << state.file_message;
    EXPECT_FALSE(unsaved_changes(state));
    const std::string text = read_file(state.template_path);
    EXPECT_NE(text.find("# Sylva's default tree: a broad oak."), std::string::npos) << text;
    EXPECT_NE(text.find("leaf_size = 0.8\n"), std::string::npos) << text;
    EXPECT_NE(text.find("crown = [0.1, 0.7, 0.2]"), std::string::npos) << text;
    EXPECT_EQ(text.find("0000000"), std::string::npos) << text;
    EXPECT_NE(text.find("fork angle, degrees"), std::string::npos);  // the grammar's own comments
    const TreeTemplate back = parse_template_file(text, state.template_path);
    EXPECT_TRUE(same_template(back, state.tree_template));

    // Saved again after opening: the comments stay where they were.
    StudioState again;
    again.template_path = state.template_path;
    open_template_file(again);
    ASSERT_FALSE(again.file_failed) << again.file_message;
    cancel_generations(again);
    again.tree_template.params.leaf_size = 0.5;
    save_template_to_file(again);
    const std::string second = read_file(again.template_path);
    EXPECT_NE(second.find("# Sylva's default tree: a broad oak."), std::string::npos);
    EXPECT_NE(second.find("leaf_size = 0.5\n"), std::string::npos);
    ASSERT_TRUE(wait_for_generations(state));
    ASSERT_TRUE(wait_for_generations(again));
}

TEST(StudioBasics, KeyCommentsSurviveASave) {
    const std::string original =
        "# my tree\n# two lines\nname = \"t\"  # its name\ndescription = \"d\"\n"
        "grammar = '''\naxiom: F # a # in the grammar\n'''\n\n"
        "# the knobs\n[params]\n# above leaf_size\nleaf_size = 0.3  # meters\n";
    const TreeTemplate t = parse_template_file(original, "t.toml");
    const std::string text = template_file_text(t, original);
    EXPECT_EQ(text.rfind("# my tree\n# two lines\nname = 't'  # its name\n", 0), 0u) << text;
    EXPECT_NE(text.find("# the knobs\n[params]\n"), std::string::npos) << text;
    EXPECT_NE(text.find("# above leaf_size\nleaf_size = 0.3  # meters\n"), std::string::npos)
        << text;
    EXPECT_NE(text.find("axiom: F # a # in the grammar\n'''"), std::string::npos) << text;
    EXPECT_TRUE(same_template(parse_template_file(text, "t.toml"), t));
}

TEST(StudioBasics, RecentFilesPersistNewestFirst) {
    TempDir dir;
    StudioState state;
    state.recent_store = (dir.path / "config" / "recent_files").string();
    for (int i = 0; i < 10; ++i)
        remember_file(state, (dir.path / (std::to_string(i) + ".toml")).string());
    remember_file(state, (dir.path / "3.toml").string());
    ASSERT_EQ(state.recent_files.size(), kMaxRecentFiles);
    EXPECT_EQ(std::filesystem::path(state.recent_files[0]).filename(), "3.toml");
    EXPECT_EQ(std::filesystem::path(state.recent_files[1]).filename(), "9.toml");
    StudioState later;
    later.recent_store = state.recent_store;
    load_recent_files(later);
    EXPECT_EQ(later.recent_files, state.recent_files);
}

}  // namespace
}  // namespace sylva::studio
