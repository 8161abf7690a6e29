// The studio's state without a window: edits, undo / redo, background generation with
// cancel, the error boundary that keeps the last good tree, and export. These are what the
// panels call every frame, so they are tested as the main loop drives them: poll, act, poll.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "tests/ui/wait_for_generations.h"
#include "tree/template_library.h"
#include "turtle/lsystem_params.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {
namespace {

using Clock = std::chrono::steady_clock;

// A small, fast tree: the default template at a low resolution.
TreeTemplate small_tree() {
    TreeTemplate t = load_template("default");
    t.params.trunk_resolution = 24;
    t.params.crown_resolution = 16;
    t.params.blocks.edit<LSystemParams>().generations = 3;
    t.params.drop_hidden = false;  // the trunk meshed at its resolution, which tests below raise
    return t;
}

StudioState state_with(const TreeTemplate& t) {
    StudioState state;
    state.tree_template = state.committed = t;
    return state;
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

// A tree in the low-poly view at `budget`, generated and shown.
StudioState low_poly_state(int budget) {
    StudioState state = state_with(small_tree());
    state.view.low_poly = true;
    state.tree_template.params.triangle_budget = budget;
    start_generation(state);
    EXPECT_TRUE(wait_for_generations(state));
    return state;
}

std::size_t part_triangles(const ModelParts& parts, const std::string& name) {
    for (const NamedMesh& part : parts)
        if (part.name == name) return part.mesh->triangles.size();
    return 0;
}

TEST(StudioState, LowPolyViewShowsTheThinnedLeavesAnExportWrites) {
    StudioState state = low_poly_state(200);
    ASSERT_TRUE(state.tree && state.tree->reduced());
    const GeneratedTree& shown = *state.tree;
    ASSERT_GT(shown.tree.leaves.triangles.size(), 200u);  // else nothing would be thinned
    const ShownParts parts = shown_parts(shown, 0);
    EXPECT_LE(parts.leaves.triangles.size(), 200u);
    EXPECT_GT(parts.leaves.triangles.size(), 0u);
    EXPECT_LT(parts.leaves.triangles.size(), shown.tree.leaves.triangles.size());
    // The very meshes of level 0 of the finished tree, as the writers get them.
    const std::vector<ModelParts> written = finished_parts(shown.tree, shown.finished, {});
    EXPECT_EQ(part_triangles(written[0], "leaves"), parts.leaves.triangles.size());
    EXPECT_EQ(&parts.leaves, &shown.finished.levels[0].leaves);
    EXPECT_EQ(&parts.trunk, &shown.finished.levels[0].trunk);

    // Low poly off: every leaf and the marching-cubes meshes, whatever level is asked for.
    StudioState raw = state_with(small_tree());
    start_generation(raw);
    ASSERT_TRUE(wait_for_generations(raw));
    const ShownParts all = shown_parts(*raw.tree, 2);
    EXPECT_EQ(all.level, 0);
    EXPECT_EQ(&all.leaves, &raw.tree->tree.leaves);
    EXPECT_EQ(&all.crown, &raw.tree->tree.crown);
}

TEST(StudioState, LodSelectorShowsEachLevelOfTheExportsChain) {
    StudioState state = low_poly_state(400);
    ASSERT_TRUE(state.tree && state.tree->reduced());
    const GeneratedTree& shown = *state.tree;
    ASSERT_EQ(shown.finished.levels.size(), static_cast<std::size_t>(kLodLevels));
    EXPECT_TRUE(shown.finished.lod);
    const std::vector<ModelParts> written = finished_parts(shown.tree, shown.finished, {});
    std::size_t previous_solids = SIZE_MAX, previous_leaves = SIZE_MAX;
    for (int level = 0; level < kLodLevels; ++level) {
        const ShownParts parts = shown_parts(shown, level);
        EXPECT_EQ(parts.level, level);
        const std::size_t solids = parts.trunk.triangles.size() + parts.crown.triangles.size();
        const std::size_t leaves = parts.leaves.triangles.size();
        EXPECT_LE(solids, previous_solids) << "level " << level;
        EXPECT_LE(leaves, previous_leaves) << "level " << level;
        EXPECT_LE(leaves, 400u >> level);
        const auto i = static_cast<std::size_t>(level);
        EXPECT_EQ(part_triangles(written[i], "trunk"), parts.trunk.triangles.size());
        EXPECT_EQ(part_triangles(written[i], "crown"), parts.crown.triangles.size());
        EXPECT_EQ(part_triangles(written[i], "leaves"), leaves);
        previous_solids = solids;
        previous_leaves = leaves;
    }
    // The coarsest level is much lighter than the finest, and a level past the chain's end
    // shows the coarsest.
    const ShownParts finest = shown_parts(shown, 0), coarsest = shown_parts(shown, 3);
    EXPECT_LT(2 * (coarsest.trunk.triangles.size() + coarsest.crown.triangles.size()),
              finest.trunk.triangles.size() + finest.crown.triangles.size());
    EXPECT_LT(coarsest.leaves.triangles.size(), finest.leaves.triangles.size());
    EXPECT_EQ(shown_parts(shown, 9).level, kLodLevels - 1);
    // Picking a level is not an edit: nothing to generate.
    state.view.lod_level = 3;
    EXPECT_FALSE(edit_pending(state));
}

TEST(StudioState, TotalsCountTheFinishedPartsAgainstTheBudget) {
    StudioState state = low_poly_state(400);
    ASSERT_TRUE(state.tree && state.tree->reduced());
    const GeneratedTree& shown = *state.tree;
    const std::vector<ModelParts> written = finished_parts(shown.tree, shown.finished, {});
    for (int level = 0; level < kLodLevels; ++level) {
        const GameMeshTotals totals = game_mesh_totals(shown, level);
        const auto i = static_cast<std::size_t>(level);
        EXPECT_EQ(totals.level, level);
        EXPECT_EQ(totals.trunk, part_triangles(written[i], "trunk"));
        EXPECT_EQ(totals.crown, part_triangles(written[i], "crown"));
        EXPECT_EQ(totals.leaves, part_triangles(written[i], "leaves"));
        std::size_t all = 0;
        for (const NamedMesh& part : written[i]) all += part.mesh->triangles.size();
        EXPECT_EQ(totals.total(), all);
        EXPECT_EQ(totals.budget, 400u >> level);
        EXPECT_EQ(totals.leaf_budget, 400u >> level);  // the leaves' share equals the total
        const bool over = totals.trunk + totals.crown > totals.budget ||
                          totals.leaves > totals.leaf_budget ||
                          !shown.finished.levels[i].within_budget;
        EXPECT_EQ(totals.over_budget, over) << "level " << level;
        EXPECT_EQ(totals.note, shown.finished.levels[i].note);
        const std::string text = totals_text(totals);
        EXPECT_NE(text.find("= " + std::to_string(all) + " triangles"), std::string::npos) << text;
        EXPECT_NE(text.find("budget " + std::to_string(400u >> level)), std::string::npos) << text;
    }
}

// Makes the worker wait, after it hands a tree over, until a poll has taken it: what a job
// shows no longer depends on how often the polling thread runs (under load a draft could be
// replaced by level 0 before any poll saw it). Construct before start_generation(), watch()
// the job right after it.
class HandOverGate {
  public:
    explicit HandOverGate(StudioState& state) {
        state.wake = [this] {
            std::unique_lock lock(mutex_);
            const int mine = ++handed_;
            changed_.wait(lock, [&] { return progress_ != nullptr; });
            JobProgress* progress = progress_;
            lock.unlock();
            {
                // Woken by the job's end (the result is set): nothing waits to be taken, and
                // the poll that takes the result joins this thread.
                const std::lock_guard handed(progress->draft_mutex);
                if (!progress->draft_tree) return;
            }
            lock.lock();
            changed_.wait_for(lock, std::chrono::seconds(30), [&] { return seen_ >= mine; });
        };
    }
    void watch(JobProgress& progress) {
        {
            const std::lock_guard lock(mutex_);
            progress_ = &progress;
        }
        changed_.notify_all();
    }
    // Polls as main does: what was handed over before the poll began is on screen after it.
    void poll(StudioState& state) {
        int handed = 0;
        {
            const std::lock_guard lock(mutex_);
            handed = handed_;
        }
        poll_jobs(state);
        {
            const std::lock_guard lock(mutex_);
            seen_ = handed;
        }
        changed_.notify_all();
    }

  private:
    std::mutex mutex_;
    std::condition_variable changed_;
    JobProgress* progress_ = nullptr;
    int handed_ = 0;
    int seen_ = 0;
};

// Polls as main does until no generation runs, keeping every tree that reached the screen.
// With a gate, every tree the job handed over is among them.
std::vector<std::shared_ptr<const GeneratedTree>> trees_shown_until_done(
    StudioState& state, HandOverGate* gate = nullptr) {
    std::vector<std::shared_ptr<const GeneratedTree>> shown;
    const Clock::time_point end = Clock::now() + std::chrono::seconds(60);
    while ((generation_running(state) || !state.stale.empty()) && Clock::now() < end) {
        if (gate)
            gate->poll(state);
        else
            poll_jobs(state);
        if (state.tree_changed) {
            shown.push_back(state.tree);
            state.tree_changed = false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_FALSE(generation_running(state));
    return shown;
}

TEST(StudioState, ASliderHeldStillShowsADraftThenItsGameMesh) {
    StudioState state = low_poly_state(300);
    ASSERT_TRUE(state.tree && state.tree->reduced());
    state.tree_changed = false;                         // main has uploaded it
    state.tree_template.params.trunk_resolution = 120;  // a reduction long enough to see a draft
    state.tree_template.params.blocks.edit<LSystemParams>().tropism += 0.1;
    set_dragging(state, true);
    ASSERT_TRUE(edit_pending(state));
    HandOverGate gate(state);
    start_generation(state);
    ASSERT_TRUE(state.job);
    gate.watch(*state.job->progress);
    EXPECT_TRUE(state.job->progress->draft);
    const auto shown = trees_shown_until_done(state, &gate);

    // Still held: the raw meshes came first, then the game mesh of the same tree, without
    // waiting for the release: its level 0, then the whole LOD chain, whose level 0 is that
    // one.
    ASSERT_EQ(shown.size(), 3u);
    EXPECT_TRUE(shown[0]->draft);
    EXPECT_FALSE(shown[0]->reduced());
    const GeneratedTree& chain = *shown.back();
    EXPECT_FALSE(chain.draft);
    ASSERT_TRUE(chain.reduced());
    EXPECT_TRUE(chain.finished.lod);
    EXPECT_EQ(chain.finished.levels.size(), static_cast<std::size_t>(kLodLevels));
    EXPECT_TRUE(same_mesh(shown[0]->tree.crown, chain.tree.crown));
    EXPECT_LE(chain.finished.levels[0].triangles, 300u);
    const GeneratedTree& level0 = *shown[1];
    EXPECT_FALSE(level0.draft);
    ASSERT_EQ(level0.finished.levels.size(), 1u);
    EXPECT_TRUE(same_mesh(level0.finished.levels[0].trunk, chain.finished.levels[0].trunk));
    EXPECT_TRUE(same_mesh(level0.finished.levels[0].crown, chain.finished.levels[0].crown));
    EXPECT_TRUE(state.dragging);
    EXPECT_FALSE(edit_pending(state));

    // Let go: the game mesh is already there; nothing runs and the release costs nothing.
    set_dragging(state, false);
    EXPECT_FALSE(edit_pending(state));
    EXPECT_FALSE(generation_running(state));
    EXPECT_EQ(state.release_ms, 0.0);
    EXPECT_FALSE(state.released_at);
}

TEST(StudioState, AMovingSliderEndsOnTheGameMeshOfItsLastValue) {
    StudioState state = low_poly_state(300);
    set_dragging(state, true);
    // Five steps of a drag, a frame apart: each value that starts a job waits for it to
    // mesh, and a job that reduces is dropped for the newer value.
    std::size_t most_workers = 0;
    for (int step = 1; step <= 5; ++step) {
        state.tree_template.params.blocks.edit<LSystemParams>().tropism = 0.05 * step;
        poll_jobs(state);
        if (edit_pending(state)) start_generation(state);
        most_workers = std::max(most_workers, state.stale.size() + (state.job ? 1 : 0));
        std::this_thread::sleep_for(std::chrono::milliseconds(15));
    }
    const Clock::time_point end = Clock::now() + std::chrono::seconds(60);
    while (generation_running(state) && Clock::now() < end) {
        poll_jobs(state);
        most_workers = std::max(most_workers, state.stale.size() + (state.job ? 1 : 0));
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_LE(most_workers, 3u);
    ASSERT_TRUE(state.tree && state.tree->reduced());
    EXPECT_FALSE(state.tree->draft);
    EXPECT_EQ(lsystem_params(state.shown_template.params).tropism, 0.25);
    EXPECT_FALSE(edit_pending(state));
    ASSERT_TRUE(wait_for_generations(state));
}

TEST(StudioState, ReleasingWhileTheJobMeshesKeepsThatJobAndTimesTheRelease) {
    StudioState state = low_poly_state(300);
    state.tree_changed = false;
    state.tree_template.params.trunk_resolution = 200;  // meshing takes a while
    set_dragging(state, true);
    start_generation(state);
    ASSERT_TRUE(state.job);
    const JobProgress* running = state.job->progress.get();

    set_dragging(state, false);  // let go at once, before the draft is done
    EXPECT_FALSE(edit_pending(state));
    ASSERT_TRUE(state.job);
    EXPECT_EQ(state.job->progress.get(), running);  // the same job, not a new one
    EXPECT_FALSE(running->draft);                   // no draft once let go
    EXPECT_TRUE(state.stale.empty());
    EXPECT_TRUE(state.released_at);
    const auto shown = trees_shown_until_done(state);
    ASSERT_FALSE(shown.empty());
    // Whether the job handed a draft over before it saw the release or not: the game mesh,
    // and the time from the release to it.
    EXPECT_TRUE(state.tree->reduced());
    EXPECT_FALSE(state.tree->draft);
    EXPECT_GT(state.release_ms, 0.0);
    EXPECT_FALSE(state.released_at);
}

TEST(StudioState, LettingGoStartsTheLastValueAtOnce) {
    StudioState state = low_poly_state(300);
    state.tree_template.params.trunk_resolution = 200;  // meshing takes a while
    set_dragging(state, true);
    start_generation(state);
    ASSERT_TRUE(state.job);
    const JobProgress* first = state.job->progress.get();
    state.tree_template.params.blocks.edit<LSystemParams>().tropism +=
        0.2;  // the slider moves on while it meshes
    start_generation(state);
    ASSERT_EQ(state.job->progress.get(), first);
    EXPECT_TRUE(state.generate_wanted);

    // Let go: the last value does not wait for the older job to mesh.
    set_dragging(state, false);
    EXPECT_FALSE(state.generate_wanted);
    ASSERT_TRUE(state.job);
    EXPECT_NE(state.job->progress.get(), first);
    EXPECT_FALSE(state.job->progress->draft);
    EXPECT_EQ(lsystem_params(state.job->tree_template.params).tropism,
              lsystem_params(state.tree_template.params).tropism);
    EXPECT_TRUE(first->cancel);
    EXPECT_TRUE(state.released_at);
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_TRUE(state.tree->reduced());
    EXPECT_EQ(lsystem_params(state.shown_template.params).tropism,
              lsystem_params(state.tree_template.params).tropism);
    EXPECT_GT(state.release_ms, 0.0);
}

TEST(StudioState, ALeafEditKeepsTheReductionAndThinsTheNewLeaves) {
    StudioState state = low_poly_state(300);
    ASSERT_TRUE(state.tree && state.tree->reduced());
    const auto before = state.tree;
    EXPECT_FALSE(before->reduction_reused);

    // Leaves only: trunk and crown come out of the meshing the same, the reduction is kept.
    state.tree_template.params.leaf_density *= 2.0;
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    const auto leafier = state.tree;
    ASSERT_TRUE(leafier->reduced());
    EXPECT_TRUE(leafier->reduction_reused);
    EXPECT_GT(leafier->tree.leaves.triangles.size(), before->tree.leaves.triangles.size());
    for (std::size_t i = 0; i < leafier->finished.levels.size(); ++i) {
        EXPECT_TRUE(same_mesh(leafier->finished.levels[i].trunk, before->finished.levels[i].trunk));
        EXPECT_TRUE(same_mesh(leafier->finished.levels[i].crown, before->finished.levels[i].crown));
        EXPECT_LE(leafier->finished.levels[i].leaves.triangles.size(),
                  leafier->finished.leaf_budgets[i]);
    }
    // ... and it is what a reduction of the new tree gives, leaves and all (what an export
    // writes).
    FinishSettings finish;
    finish.budget.total = 300;
    finish.lod = true;
    finish.lod_levels = kLodLevels;
    const FinishedTree fresh = finish_tree(leafier->tree, finish);
    ASSERT_EQ(fresh.levels.size(), leafier->finished.levels.size());
    for (std::size_t i = 0; i < fresh.levels.size(); ++i) {
        EXPECT_TRUE(same_mesh(fresh.levels[i].trunk, leafier->finished.levels[i].trunk)) << i;
        EXPECT_TRUE(same_mesh(fresh.levels[i].crown, leafier->finished.levels[i].crown)) << i;
        EXPECT_TRUE(same_mesh(fresh.levels[i].leaves, leafier->finished.levels[i].leaves)) << i;
    }

    // The crown shape (a reduction setting of the template): the same meshes, reduced
    // again, to what an export of the template writes (hulls: the small tree's crown has
    // no handle, so the automatic choice was its own surface).
    state.tree_template.params.crown_shape = CrownShape::Hulls;
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_FALSE(state.tree->reduction_reused);
    EXPECT_TRUE(same_mesh(state.tree->tree.crown, leafier->tree.crown));
    EXPECT_FALSE(
        same_mesh(state.tree->finished.levels[0].crown, leafier->finished.levels[0].crown));
    finish.budget.crown_shape = CrownShape::Hulls;
    EXPECT_TRUE(same_mesh(finish_tree(leafier->tree, finish).levels[0].crown,
                          state.tree->finished.levels[0].crown));

    // A shape edit meshes another trunk: reduced again.
    state.tree_template.params.blocks.edit<LSystemParams>().tropism += 0.2;
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_FALSE(state.tree->reduction_reused);
    EXPECT_FALSE(same_mesh(state.tree->tree.trunk, leafier->tree.trunk));
}

TEST(StudioState, AReductionIsReusedOnlyForTheSameMeshesAndBudget) {
    StudioState state = low_poly_state(300);
    const GeneratedTree& shown = *state.tree;
    ASSERT_TRUE(shown.reduced());
    EXPECT_TRUE(reuse_reduction(shown, shown.tree, 300));
    EXPECT_FALSE(reuse_reduction(shown, shown.tree, 200));  // another budget
    Tree moved = shown.tree;
    moved.crown.positions[0].x += 0.01f;
    EXPECT_FALSE(reuse_reduction(shown, moved, 300));
    Tree reshaped = shown.tree;  // the same meshes, the crown drawn another way
    reshaped.crown_shape = CrownShape::Blobs;
    EXPECT_FALSE(reuse_reduction(shown, reshaped, 300));
    // The marching-cubes meshes alone (low poly was off): nothing to reuse.
    GeneratedTree raw;
    raw.tree = shown.tree;
    EXPECT_FALSE(reuse_reduction(raw, shown.tree, 300));
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
    state.tree_template.params.drop_hidden = false;  // else the trunk is meshed for the budget
    state.tree_template.params.branch_style =        // else it is drawn, not meshed
        BranchStyle::Surface;
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

// A frame drawn for a job nobody waits for takes the cores from the one that replaced it
// (a software renderer's frame takes both cores for a while): a cancelled job ends without waking
// the UI, unless the newest edit waits for it to end (two already winding down).
TEST(StudioState, ACancelledJobWakesTheUiOnlyWhenANewerJobWaitsForIt) {
    std::atomic<int> cancelled_wakes{0}, newer_wakes{0};
    StudioState state = state_with(load_template("default"));
    state.wake = [&cancelled_wakes] { ++cancelled_wakes; };
    state.tree_template.params.drop_hidden = false;  // else the trunk is meshed for the budget
    state.tree_template.params.branch_style =        // else it is drawn, not meshed
        BranchStyle::Surface;
    state.tree_template.params.trunk_resolution = 1200;  // seconds of meshing
    start_generation(state);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    state.wake = [&newer_wakes] { ++newer_wakes; };
    state.tree_template.params.trunk_resolution = 24;
    start_generation(state);
    ASSERT_EQ(state.stale.size(), 1u);
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_EQ(cancelled_wakes, 0);  // its end drew no frame
    EXPECT_GE(newer_wakes, 1);      // the job that replaced it woke the UI for its tree

    // Two jobs winding down: the third edit waits for them (poll_jobs starts it), and
    // their ends wake the UI so it does not wait for a timeout.
    state.wake = [&cancelled_wakes] { ++cancelled_wakes; };
    for (int resolution : {1200, 1100}) {
        state.tree_template.params.trunk_resolution = resolution;
        start_generation(state);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    state.tree_template.params.trunk_resolution = 26;
    start_generation(state);
    ASSERT_EQ(state.stale.size(), 2u);
    ASSERT_TRUE(state.generate_wanted);
    for (GenerationJob& job : state.stale) job.result.wait();
    // The worker wakes the UI just after its result is set.
    const Clock::time_point end = Clock::now() + std::chrono::seconds(5);
    while (cancelled_wakes == 0 && Clock::now() < end)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    EXPECT_GE(cancelled_wakes, 1);
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_EQ(state.shown_template.params.trunk_resolution, 26);
}

TEST(StudioState, UndoAndRedoStepThroughCommittedEdits) {
    StudioState state = state_with(small_tree());
    const double first = lsystem_params(state.tree_template.params).tropism;
    state.tree_template.params.blocks.edit<LSystemParams>().tropism = 0.5;
    EXPECT_TRUE(commit_edit(state));
    EXPECT_FALSE(commit_edit(state));  // nothing new
    state.tree_template.grammar += "\n# a comment\n";
    EXPECT_TRUE(commit_edit(state));
    ASSERT_EQ(state.undo.size(), 2u);

    undo(state);
    EXPECT_EQ(state.tree_template.grammar, small_tree().grammar);
    EXPECT_EQ(lsystem_params(state.tree_template.params).tropism, 0.5);
    undo(state);
    EXPECT_EQ(lsystem_params(state.tree_template.params).tropism, first);
    EXPECT_TRUE(state.undo.empty());
    undo(state);  // nothing left: no change
    EXPECT_EQ(lsystem_params(state.tree_template.params).tropism, first);

    redo(state);
    redo(state);
    EXPECT_EQ(lsystem_params(state.tree_template.params).tropism, 0.5);
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
    state.tree_template.params.blocks.edit<LSystemParams>().tropism =
        0.4;  // not committed yet (a drag in progress)
    undo(state);
    EXPECT_EQ(lsystem_params(state.tree_template.params).tropism,
              lsystem_params(small_tree().params).tropism);
    redo(state);
    EXPECT_EQ(lsystem_params(state.tree_template.params).tropism, 0.4);
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
    other.saved = other.tree_template;  // opened, not edited: no "discard changes?"
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

TEST(StudioState, ExportWritesTheGameMeshTheViewShows) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sylva_test_ui";
    std::filesystem::create_directories(dir);
    StudioState state = low_poly_state(300);
    ASSERT_TRUE(state.tree && state.tree->reduced());
    auto export_now = [&state](bool lod) {
        state.export_settings.lod = lod;
        start_export(state);
        const Clock::time_point end = Clock::now() + std::chrono::seconds(60);
        while (state.export_job.valid() && Clock::now() < end) {
            poll_jobs(state);
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        EXPECT_FALSE(state.export_failed) << state.export_message;
        return state.export_message;
    };
    state.export_settings.path = (dir / "game.obj").string();
    const GameMeshTotals totals = game_mesh_totals(*state.tree, 0);
    const std::string one = export_now(false);
    EXPECT_NE(one.find("trunk " + std::to_string(totals.trunk)), std::string::npos) << one;
    EXPECT_NE(one.find("crown " + std::to_string(totals.crown)), std::string::npos) << one;
    EXPECT_NE(one.find("leaves " + std::to_string(totals.leaves)), std::string::npos) << one;
    const std::string chain = export_now(true);
    EXPECT_NE(chain.find("LOD0-LOD3"), std::string::npos) << chain;
}

// Typing trunk_resolution 1500 must not freeze the studio. A job estimated over the limits
// is not started; its estimate is shown until "run anyway" or a cheaper edit.
TEST(StudioState, ACostlyEditIsHeldBackWithItsEstimate) {
    TreeTemplate costly = small_tree();
    costly.params.trunk_resolution = 1500;
    StudioState state = state_with(costly);
    start_generation(state);
    EXPECT_FALSE(generation_running(state));
    EXPECT_NE(state.cost_warning.find("GB"), std::string::npos) << state.cost_warning;
    EXPECT_FALSE(edit_pending(state));  // not retried every frame

    state.tree_template = small_tree();
    start_generation(state);
    EXPECT_TRUE(state.cost_warning.empty());
    ASSERT_TRUE(wait_for_generations(state));
    EXPECT_TRUE(state.tree);
}

// Picking or opening another template over unsaved edits waits for "discard changes?";
// discarding switches (and frames the new tree), keeping the edits changes nothing.
TEST(StudioState, SwitchingTemplatesAsksBeforeDroppingUnsavedEdits) {
    StudioState state;
    load_template_into(state, load_template("oak"));
    EXPECT_TRUE(switch_template(state, {load_template("birch"), {}, {}}));  // nothing to lose
    EXPECT_EQ(state.tree_template.name, "birch");
    EXPECT_TRUE(state.frame_next_tree);

    state.tree_template.params.seed += 1;  // an edit
    ASSERT_TRUE(unsaved_changes(state));
    const std::string path = state.template_path;
    EXPECT_FALSE(switch_template(state, {load_template("palm"), {}, {}}));
    EXPECT_EQ(state.tree_template.name, "birch");
    ASSERT_TRUE(state.pending_switch);
    cancel_switch(state);
    EXPECT_FALSE(state.pending_switch);
    EXPECT_EQ(state.tree_template.name, "birch");
    EXPECT_TRUE(unsaved_changes(state));

    const auto file = std::filesystem::temp_directory_path() / "sylva_switch_test.toml";
    {
        StudioState writer;
        load_template_into(writer, load_template("pine"));
        writer.template_path = file.string();
        save_template_to_file(writer);
        ASSERT_FALSE(writer.file_failed) << writer.file_message;
    }
    open_template_file(state, file.string());
    EXPECT_EQ(state.tree_template.name, "birch");  // waits
    EXPECT_EQ(state.template_path, path);          // Save still writes where it did
    ASSERT_TRUE(state.pending_switch);
    state.frame_next_tree = false;
    confirm_switch(state);
    EXPECT_EQ(state.tree_template.name, "pine");
    EXPECT_EQ(state.template_path, file.string());
    EXPECT_FALSE(unsaved_changes(state));
    EXPECT_TRUE(state.frame_next_tree);  // the camera frames the new tree
    undo(state);                         // the dropped edits come back
    EXPECT_EQ(state.tree_template.name, "birch");
    cancel_generations(state);
    EXPECT_TRUE(wait_for_generations(state));
    std::filesystem::remove(file);
}

// The Export section's budget is the export's: it edits no template (no unsaved mark, no
// new tree) until "keep in template" makes it the template's budget, as an undoable edit.
TEST(StudioState, TheExportBudgetIsNoTemplateEditUntilKept) {
    StudioState state;
    load_template_into(state, load_template("oak"));
    cancel_generations(state);
    const int template_budget = state.tree_template.params.triangle_budget;
    EXPECT_EQ(export_budget(state), static_cast<std::size_t>(template_budget));
    state.export_settings.budget = 1500;
    EXPECT_EQ(export_budget(state), 1500u);
    EXPECT_EQ(state.tree_template.params.triangle_budget, template_budget);
    EXPECT_FALSE(unsaved_changes(state));
    keep_export_budget(state);
    EXPECT_EQ(state.tree_template.params.triangle_budget, 1500);
    EXPECT_TRUE(unsaved_changes(state));
    EXPECT_EQ(state.export_settings.budget, -1);  // follows the template again
    EXPECT_EQ(export_budget(state), 1500u);
    undo(state);
    EXPECT_EQ(state.tree_template.params.triangle_budget, template_budget);
    cancel_generations(state);
    EXPECT_TRUE(wait_for_generations(state));
}

// The budget table: one line per part, trunk and crown against their shared target, leaves
// against theirs, the total against both; the game mesh of the view adds up.
TEST(StudioState, TheBudgetTableHasALinePerPart) {
    StudioState state = state_with(small_tree());
    state.view.low_poly = true;
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    ASSERT_TRUE(state.tree && state.tree->reduced());
    const GameMeshTotals totals = game_mesh_totals(*state.tree, 0);
    const std::vector<BudgetLine> lines = budget_lines(totals);
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_EQ(lines[0].part, "trunk");
    EXPECT_EQ(lines[1].part, "crown");
    EXPECT_EQ(lines[3].part, "leaves");
    EXPECT_EQ(lines[4].part, "total");
    EXPECT_EQ(lines[0].triangles + lines[1].triangles, lines[2].triangles);
    EXPECT_EQ(lines[2].triangles + lines[3].triangles, lines[4].triangles);
    EXPECT_EQ(lines[2].target, export_budget(state));
    EXPECT_EQ(lines[4].target, lines[2].target + lines[3].target);
    EXPECT_GT(lines[0].triangles, 0u);
    EXPECT_FALSE(lines[2].over);
}

// Exporting into a folder that does not exist writes nothing and names the folder; creating
// it exports, and the message says what was written.
TEST(StudioState, ExportAsksToCreateAMissingFolder) {
    const auto dir = std::filesystem::temp_directory_path() / "sylva_test_missing";
    std::filesystem::remove_all(dir);
    StudioState state = state_with(small_tree());
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    state.export_settings.path = (dir / "deeper" / "tree.obj").string();
    start_export(state);
    EXPECT_FALSE(state.export_job.valid());
    EXPECT_EQ(state.export_missing_folder, (dir / "deeper").string());
    EXPECT_FALSE(std::filesystem::exists(dir));
    create_export_folder(state);
    EXPECT_TRUE(state.export_missing_folder.empty());
    ASSERT_TRUE(state.export_job.valid());
    state.export_job.wait();
    poll_jobs(state);
    EXPECT_FALSE(state.export_failed) << state.export_message;
    EXPECT_NE(state.export_message.find("tree.obj"), std::string::npos) << state.export_message;
    EXPECT_TRUE(std::filesystem::exists(dir / "deeper" / "tree.obj"));
    std::filesystem::remove_all(dir);
}

// A failed export into folders it made leaves none of them behind.
TEST(StudioState, FailedExportRemovesTheFolderItMade) {
    const auto dir = std::filesystem::temp_directory_path() / "sylva_test_failed_export";
    std::filesystem::remove_all(dir);
    StudioState state = state_with(small_tree());
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    state.export_settings.path = (dir / "deeper" / "tree.unknown").string();  // no such format
    start_export(state);
    ASSERT_FALSE(state.export_missing_folder.empty());
    create_export_folder(state);
    ASSERT_TRUE(state.export_job.valid());
    state.export_job.wait();
    poll_jobs(state);
    EXPECT_TRUE(state.export_failed) << state.export_message;
    EXPECT_FALSE(std::filesystem::exists(dir));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sylva::studio
