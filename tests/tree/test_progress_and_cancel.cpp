// Cost awareness, headless: the growth reports a rising fraction that ends at 1
// (the studio's progress bar and time left), and a heavy reduction answers a cancel set
// from another thread long before it would have finished. The 100 ms goal is measured by
// sylva-bench-cancel; the bound here is looser so it holds under sanitizers on a loaded
// machine, but far below the seconds the work takes without polling.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <limits>
#include <thread>
#include <vector>

#include "core/cancel.h"
#include "core/growth.h"
#include "lowpoly/decimate.h"
#include "lowpoly/handle_cutting.h"
#include "tree/growth.h"
#include "tree/lowpoly_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_params.h"
#include "turtle/lsystem_parser.h"

namespace sylva {
namespace {

using Clock = std::chrono::steady_clock;

// Every fraction in [0, 1], none below the one before, the last exactly 1.
void expect_rising_to_one(const std::vector<float>& fractions) {
    ASSERT_FALSE(fractions.empty());
    for (std::size_t i = 0; i < fractions.size(); ++i) {
        EXPECT_GE(fractions[i], 0.0f) << i;
        EXPECT_LE(fractions[i], 1.0f) << i;
        if (i > 0) {
            EXPECT_GE(fractions[i], fractions[i - 1]) << i;
        }
    }
    EXPECT_EQ(fractions.back(), 1.0f);
}

TEST(GrowthProgress, TheDerivationReportsWithinALongStep) {
    const LSystem system = parse_lsystem("axiom: F\nF -> FF\n", {});
    DeriveSettings settings;
    settings.steps = 16;  // the last step rewrites 32768 modules
    std::vector<float> fractions;
    settings.progress = [&](float f) { fractions.push_back(f); };
    const Word word = derive(system, settings);
    EXPECT_EQ(word.size(), 65536u);
    expect_rising_to_one(fractions);
    // More reports than steps: the long steps report as they go, and the late, large steps
    // have most of the bar (the last step alone doubles the word).
    EXPECT_GT(fractions.size(), 16u + 8u);
    std::size_t below_half = 0;
    for (float f : fractions) below_half += f < 0.5f;
    EXPECT_LT(below_half, fractions.size() - 4);
}

TEST(GrowthProgress, EveryGrowthMethodRisesToOne) {
    for (const char* name : {"ternary", "oak", "elm", "hedge"}) {
        TreeTemplate t = load_template(name);
        std::vector<float> fractions;
        GrowthContext context;
        context.progress = [&](float f) { fractions.push_back(f); };
        const Skeleton skeleton = grow(t, context);
        EXPECT_FALSE(skeleton.segments.empty()) << name;
        SCOPED_TRACE(name);
        expect_rising_to_one(fractions);
        // Something between the start and the end, not just a final 1.
        EXPECT_GE(fractions.size(), 3u);
        EXPECT_TRUE(std::any_of(fractions.begin(), fractions.end(),
                                [](float f) { return f > 0.0f && f < 1.0f; }));
    }
}

TEST(GrowthProgress, ThePipelineHandsItOn) {
    TreeTemplate t = load_template("ternary");
    t.params.blocks.edit<LSystemParams>().generations = 5;
    std::vector<float> fractions;
    MeshOptions options;
    options.growth_progress = [&](float f) { fractions.push_back(f); };
    generate_tree(t, options);
    expect_rising_to_one(fractions);
}

TEST(MeshingProgress, RisesToOneWhileTrunkPiecesAndCrownAreMeshedBesideEachOther) {
    // The ternary's game mesh: its trunk in pieces and its crown meshed at once, each
    // reporting from its own threads; what the caller sees still only rises, to exactly 1.
    // The progress is called one at a time: the vector needs no lock.
    // With prisms (the default) the crown's meshing is the whole bar.
    for (std::size_t budget : {std::size_t{0}, std::size_t{3000}, std::size_t{800}}) {
        std::vector<float> fractions;
        MeshOptions options;
        options.budget = budget;
        options.progress = [&](float f) { fractions.push_back(f); };
        TreeTemplate t = load_template("ternary");
        if (budget == 3000) t.params.branch_style = BranchStyle::Surface;
        const Tree tree = generate_tree(t, options);
        ASSERT_FALSE(tree.crown.triangles.empty());
        SCOPED_TRACE(budget);
        expect_rising_to_one(fractions);
        // Both halves of the bar: the crown's half is not all at the end, nor the trunk's.
        EXPECT_TRUE(std::any_of(fractions.begin(), fractions.end(),
                                [](float f) { return f > 0.1f && f < 0.9f; }));
    }
}

// How soon cancelled work must stop: within a second, three in a sanitizer build, whose
// checks slow the work between two polls of the flag several times over.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr double kStopsWithinSeconds = 3.0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr double kStopsWithinSeconds = 3.0;
#else
constexpr double kStopsWithinSeconds = 1.0;
#endif
#else
constexpr double kStopsWithinSeconds = 1.0;
#endif

// Runs `work` with the flag set 50 ms in; the seconds from setting it to the throw.
double seconds_to_cancel(const std::function<void(CancelFlag)>& work) {
    std::atomic<bool> cancel{false};
    std::atomic<bool> done{false};
    Clock::time_point set_at{};
    std::thread setter([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        set_at = Clock::now();
        cancel = true;
    });
    bool cancelled = false;
    try {
        work(&cancel);
    } catch (const Cancelled&) {
        cancelled = true;
    }
    const Clock::time_point end = Clock::now();
    done = true;
    setter.join();
    EXPECT_TRUE(cancelled) << "the work finished before the flag was set";
    return std::chrono::duration<double>(end - set_at).count();
}

// The ternary tree at 7 generations as the studio meshes it for 800 triangles: hundreds of
// handles where its branches cross, so cutting them (lowpoly/handle_cutting.h) takes many
// seconds.
const Tree& crossing_tree() {
    static const Tree tree = [] {
        TreeTemplate t = load_template("ternary");
        t.params.blocks.edit<LSystemParams>().generations = 7;
        t.params.branch_style = BranchStyle::Surface;  // meshed, not drawn
        MeshOptions options;
        options.budget = 800;
        return generate_tree(t, options);
    }();
    return tree;
}

TEST(Cancel, HandleCuttingStopsSoonAfterTheFlagIsSet) {
    Mesh trunk = crossing_tree().trunk;
    ASSERT_GT(genus(trunk), 50u);
    // Without polling this cuts every handle (each round 64 searches over the whole mesh).
    const double seconds = seconds_to_cancel([&](CancelFlag cancel) {
        cut_handles(trunk, std::numeric_limits<std::size_t>::max(), cancel);
    });
    EXPECT_LT(seconds, kStopsWithinSeconds);
}

TEST(Cancel, AHeavyReductionStopsSoonAfterTheFlagIsSet) {
    const Tree& tree = crossing_tree();
    const double seconds = seconds_to_cancel([&](CancelFlag cancel) {
        DecimateSettings settings;
        settings.cancel = cancel;
        TreeBudget budget;
        budget.total = 800;
        reduce_tree(tree, budget, settings);
    });
    EXPECT_LT(seconds, kStopsWithinSeconds);
}

}  // namespace
}  // namespace sylva
