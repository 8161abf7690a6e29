// The scripted slider drag behind `sylva-studio --bench-release`: it waits for the first game
// mesh, moves the parameter one step per frame while "held", lets go, and is done only when
// the game mesh of the value let go at is what the view shows. Driven headless as main
// drives it.
#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>

#include "tree/template_library.h"
#include "turtle/lsystem_params.h"
#include "ui/state/release_bench.h"
#include "ui/state/studio_options.h"

namespace sylva::studio {
namespace {

TEST(ReleaseBench, ParsesAParameterAndItsValue) {
    const ReleaseBench bench = parse_release_bench("tropism=0.6");
    EXPECT_EQ(bench.key, "tropism");
    EXPECT_EQ(bench.target, 0.6);
    EXPECT_THROW(parse_release_bench("tropism"), std::invalid_argument);
    EXPECT_THROW(parse_release_bench("no_such_key=1"), std::invalid_argument);
    EXPECT_THROW(parse_release_bench("tropism=high"), std::invalid_argument);

    const char* args[] = {"sylva-studio", "--bench-release", "tropism=0.6", "--bench-hold", "250"};
    const StudioOptions options = parse_studio_options(5, args);
    ASSERT_TRUE(options.bench_release);
    EXPECT_EQ(*options.bench_release, "tropism=0.6");
    EXPECT_EQ(options.bench_hold_ms, 250.0);
    EXPECT_TRUE(options.low_poly);  // the bench measures the game mesh
    const char* bad[] = {"sylva-studio", "--bench-hold", "-3"};
    EXPECT_THROW(parse_studio_options(3, bad), UsageError);
}

TEST(ReleaseBench, DragsHoldsLetsGoAndWaitsForTheGameMeshOfTheLastValue) {
    StudioState state;
    state.tree_template = state.committed = load_template("default");
    state.tree_template.params.trunk_resolution = 24;
    state.tree_template.params.crown_resolution = 16;
    state.tree_template.params.blocks.edit<LSystemParams>().generations = 3;
    state.tree_template.params.triangle_budget = 300;
    state.view.low_poly = true;
    ReleaseBench bench = parse_release_bench("tropism=0.3");
    bench.steps = 3;

    // As main's loop: poll, drive (the slider), start what is pending, "draw".
    auto frame = [&] {
        poll_jobs(state);
        state.tree_changed = false;  // uploaded
        set_dragging(state, drive_release_bench(bench, state));
        if (edit_pending(state)) start_generation(state);
        return release_bench_done(bench, state);
    };
    start_generation(state);
    std::vector<double> held_values;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!frame() && std::chrono::steady_clock::now() < end) {
        if (state.dragging)
            held_values.push_back(lsystem_params(state.tree_template.params).tropism);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_EQ(bench.phase, ReleaseBench::Done);
    // Three steps from the template's value to the target, the last one exact.
    ASSERT_GE(held_values.size(), 3u);
    EXPECT_LT(held_values[0], held_values[1]);
    EXPECT_EQ(held_values[2], 0.3);
    EXPECT_FALSE(state.dragging);
    ASSERT_TRUE(state.tree && state.tree->reduced());
    EXPECT_FALSE(state.tree->draft);
    EXPECT_EQ(lsystem_params(state.shown_template.params).tropism, 0.3);
    EXPECT_GE(bench.release_ms, 0.0);
    EXPECT_NE(release_bench_report(bench, state).find("release -> game mesh on screen"),
              std::string::npos);
}

}  // namespace
}  // namespace sylva::studio
