// The studio's state without a window: edits, undo / redo, background generation with
// cancel, the error boundary that keeps the last good tree, and export. These are what the
// panels call every frame, so they are tested as the main loop drives them: poll, act, poll.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "tree/template_library.h"
#include "ui/studio_state.h"

namespace sylva::studio {
namespace {

using Clock = std::chrono::steady_clock;

// A small, fast tree: the default template at a low resolution.
TreeTemplate small_tree() {
    TreeTemplate t = load_template("default");
    t.params.trunk_resolution = 24;
    t.params.crown_resolution = 16;
    t.params.generations = 3;
    return t;
}

StudioState state_with(const TreeTemplate& t) {
    StudioState state;
    state.tree_template = state.committed = t;
    return state;
}

// The main loop's part: poll until no generation runs (or time runs out).
bool wait_for_generations(StudioState& state,
                          std::chrono::seconds limit = std::chrono::seconds(60)) {
    const Clock::time_point end = Clock::now() + limit;
    while (Clock::now() < end) {
        poll_jobs(state);
        if (!generation_running(state) && state.stale.empty()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

TEST(StudioState, GeneratesOnAWorkerAndShowsTheTree) {
    StudioState state = state_with(small_tree());
    start_generation(state);
    EXPECT_TRUE(generation_running(state));
    ASSERT_TRUE(wait_for_generations(state));
    ASSERT_TRUE(state.tree);
    EXPECT_TRUE(state.tree_changed);
    EXPECT_FALSE(state.tree->tree.trunk.triangles.empty());
    EXPECT_FALSE(state.tree->reduced());  // the low-poly view is off
    EXPECT_TRUE(state.error.empty());
    EXPECT_FALSE(edit_pending(state));
}

TEST(StudioState, LowPolyViewReducesToTheBudget) {
    StudioState state = state_with(small_tree());
    state.view.low_poly = true;
    state.tree_template.params.triangle_budget = 300;
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    ASSERT_TRUE(state.tree && state.tree->reduced());
    EXPECT_LE(state.tree->finished.levels[0].triangles, 300u);
    EXPECT_EQ(state.tree->budget, 300u);
    // Changing the budget is an edit the view must follow.
    state.tree_template.params.triangle_budget = 200;
    EXPECT_TRUE(edit_pending(state));
}

TEST(StudioState, ABrokenRuleKeepsTheLastGoodTreeAndNamesTheLine) {
    StudioState state = state_with(small_tree());
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    ASSERT_TRUE(state.tree);
    const auto good = state.tree;

    state.tree_template.grammar += "\nA -> F[(\n";
    ASSERT_TRUE(edit_pending(state));
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_EQ(state.tree, good);  // the same tree object: still on screen
    EXPECT_FALSE(state.error.empty());
    EXPECT_GT(state.error_line, 1);
    EXPECT_GT(state.error_column, 0);
    EXPECT_FALSE(edit_pending(state));  // live mode does not retry the same broken text

    state.tree_template.grammar = small_tree().grammar;  // fixed
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_TRUE(state.error.empty());
    EXPECT_EQ(state.error_line, 0);
    EXPECT_NE(state.tree, good);
}

TEST(StudioState, ANewerEditCancelsTheStaleJobWithoutBlocking) {
    StudioState state = state_with(load_template("default"));
    state.tree_template.params.trunk_resolution = 1200;  // seconds of meshing
    start_generation(state);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // let it start meshing

    // Each edit of a slider drag starts a generation; none may wait for the big one.
    for (int resolution : {30, 28, 26, 24}) {
        state.tree_template.params.trunk_resolution = resolution;
        const Clock::time_point start = Clock::now();
        start_generation(state);
        poll_jobs(state);
        EXPECT_LT(Clock::now() - start, std::chrono::milliseconds(50));
        EXPECT_LE(state.stale.size(), 2u);  // never a pile of cancelled workers
    }
    ASSERT_TRUE(wait_for_generations(state));
    ASSERT_TRUE(state.tree);
    EXPECT_TRUE(state.error.empty()) << state.error;  // a cancel is not an error
    // The tree on screen is the last edit's, not the cancelled big one's.
    EXPECT_EQ(state.shown_template.params.trunk_resolution, 24);
}

TEST(StudioState, UndoAndRedoStepThroughCommittedEdits) {
    StudioState state = state_with(small_tree());
    const double first = state.tree_template.params.tropism;
    state.tree_template.params.tropism = 0.5;
    EXPECT_TRUE(commit_edit(state));
    EXPECT_FALSE(commit_edit(state));  // nothing new
    state.tree_template.grammar += "\n# a comment\n";
    EXPECT_TRUE(commit_edit(state));
    ASSERT_EQ(state.undo.size(), 2u);

    undo(state);
    EXPECT_EQ(state.tree_template.grammar, small_tree().grammar);
    EXPECT_EQ(state.tree_template.params.tropism, 0.5);
    undo(state);
    EXPECT_EQ(state.tree_template.params.tropism, first);
    EXPECT_TRUE(state.undo.empty());
    undo(state);  // nothing left: no change
    EXPECT_EQ(state.tree_template.params.tropism, first);

    redo(state);
    redo(state);
    EXPECT_EQ(state.tree_template.params.tropism, 0.5);
    EXPECT_NE(state.tree_template.grammar, small_tree().grammar);
    EXPECT_TRUE(state.redo.empty());

    // A new edit after an undo drops the redo branch.
    undo(state);
    state.tree_template.params.seed = 77;
    commit_edit(state);
    EXPECT_TRUE(state.redo.empty());
    cancel_generations(state);
    wait_for_generations(state);
}

TEST(StudioState, UndoCommitsAnEditInProgressFirst) {
    StudioState state = state_with(small_tree());
    state.tree_template.params.tropism = 0.4;  // not committed yet (a drag in progress)
    undo(state);
    EXPECT_EQ(state.tree_template.params.tropism, small_tree().params.tropism);
    redo(state);
    EXPECT_EQ(state.tree_template.params.tropism, 0.4);
    cancel_generations(state);
    wait_for_generations(state);
}

TEST(StudioState, PickingATemplateCanBeUndone) {
    StudioState state = state_with(small_tree());
    load_template_into(state, load_template("spruce"));
    EXPECT_EQ(state.tree_template.name, "spruce");
    EXPECT_TRUE(state.frame_next_tree);
    undo(state);
    EXPECT_EQ(state.tree_template.name, small_tree().name);
    EXPECT_EQ(state.tree_template.params.trunk_resolution, 24);
    cancel_generations(state);
    wait_for_generations(state);
}

TEST(StudioState, SavedTemplateOpensAsTheSameEdit) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sylva_test_ui";
    std::filesystem::create_directories(dir);
    StudioState state = state_with(small_tree());
    state.tree_template.params.seed = 4242;
    state.template_path = (dir / "mine.toml").string();
    save_template_to_file(state);
    EXPECT_FALSE(state.file_failed) << state.file_message;

    StudioState other = state_with(load_template("spruce"));
    other.template_path = state.template_path;
    open_template_file(other);
    EXPECT_FALSE(other.file_failed) << other.file_message;
    EXPECT_TRUE(same_template(other.tree_template, state.tree_template));

    other.template_path = (dir / "missing.toml").string();
    open_template_file(other);
    EXPECT_TRUE(other.file_failed);
    EXPECT_NE(other.file_message.find("missing.toml"), std::string::npos);
    cancel_generations(other);
    wait_for_generations(other);
}

TEST(StudioState, ExportsTheTreeOnScreenAndReports) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sylva_test_ui";
    std::filesystem::create_directories(dir);
    StudioState state = state_with(small_tree());
    start_export(state);
    EXPECT_TRUE(state.export_failed);  // nothing generated yet

    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    for (const char* name : {"tree.obj", "tree.glb", "tree.ply", "tree.stl"}) {
        const std::filesystem::path path = dir / name;
        std::filesystem::remove(path);
        state.export_settings.path = path.string();
        start_export(state);
        const Clock::time_point end = Clock::now() + std::chrono::seconds(60);
        while (state.export_job.valid() && Clock::now() < end) {
            poll_jobs(state);
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        if (path.extension() == ".stl") {
            EXPECT_TRUE(state.export_failed);
            EXPECT_NE(state.export_message.find(".stl"), std::string::npos) << state.export_message;
            EXPECT_FALSE(std::filesystem::exists(path));
        } else {
            EXPECT_FALSE(state.export_failed) << state.export_message;
            EXPECT_EQ(state.export_message.rfind("wrote ", 0), 0u) << state.export_message;
            EXPECT_TRUE(std::filesystem::exists(path)) << path;
        }
    }
}

}  // namespace
}  // namespace sylva::studio
