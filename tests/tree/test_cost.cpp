// Cost is known before work starts: every reproducer is either bounded
// (few primitives per sample, a bounded leaf grid) or refused at once with the estimate.
#include <gtest/gtest.h>

#include <string>

#include "colonization/colonization_params.h"
#include "core/errors.h"
#include "tree/cost.h"
#include "tree/growth.h"
#include "tree/leaves.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"
#include "turtle/lsystem_params.h"

namespace sylva {
namespace {

TreeTemplate grammar(const std::string& text, int generations) {
    TreeTemplate t = default_template();
    t.grammar = text;
    t.params.blocks.edit<LSystemParams>().generations = generations;
    return t;
}

// 4^n copies of one segment and of one tip sphere give one cone and one sphere, not minutes
// of meshing.
TEST(Cost, CoincidentSegmentsGiveOneConeAndOneSphere) {
    const TreeTemplate t = grammar("axiom: !(0.1)F\nF -> [F][F][F][F]\n", 7);
    const Tree tree = generate_tree(t);
    ASSERT_EQ(tree.skeleton.segments.size(), 16384u);
    const TreeFields fields = tree_fields(tree.skeleton, t.params);
    ASSERT_TRUE(fields.trunk && fields.crown);
    EXPECT_EQ(fields.trunk->cones().size(), 1u);
    EXPECT_EQ(fields.crown->balls().size(), 1u);
    EXPECT_FALSE(tree.trunk.triangles.empty());
}

// A crown box 1e10 m long would take minutes of scattering leaves: it is refused by its
// extent.
TEST(Cost, ATreeOfTenMillionKilometresIsRefused) {
    EXPECT_THROW(generate_tree(grammar("axiom: !(0.1)[F(1e10)]|F(1e10)\n", 0)), InputError);
}

// The leaf grid itself has at most max_leaves cells, however thin and long the box.
TEST(Cost, TheLeafGridIsBoundedByMaxLeaves) {
    for (const glm::vec3 extent : {glm::vec3(1e10f, 0.1f, 0.1f), glm::vec3(1e5f, 1e-3f, 1e5f),
                                   glm::vec3(3.0f, 3.0f, 3.0f)}) {
        LeafSettings settings;
        settings.max_leaves = 10'000;
        settings.density = 1e6;
        std::size_t samples = 0;
        scatter_leaves(
            [&samples](const glm::vec3&) {
                ++samples;
                return 1.0f;
            },
            Box{glm::vec3(0.0f), extent}, settings);
        EXPECT_LE(samples, settings.max_leaves);
        EXPECT_GT(samples, settings.max_leaves / 100);
    }
}

// skeleton --steps 21 of F -> FF would take gigabytes and a minute: the estimate knows the
// word exactly and is over the default limits; raising them lets it through.
TEST(Cost, DoublingGrammarIsEstimatedAndRefusedBeforeDeriving) {
    const TreeTemplate t = grammar("axiom: !(0.1)F\nF -> FF\n", 21);
    const Cost cost = estimate_cost(t, 0, false);
    EXPECT_EQ(cost.modules, 2097153.0);
    EXPECT_EQ(cost.segments, 2097152.0);
    EXPECT_GT(cost.bytes, 2e9);
    EXPECT_GT(cost.seconds, 10.0);
    try {
        check_cost(cost, {}, "raise --max-memory");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("2097153 modules"), std::string::npos) << message;
        EXPECT_NE(message.find("--max-memory"), std::string::npos) << message;
    }
    EXPECT_NO_THROW(check_cost(cost, {1e12, 1e6}, ""));
}

// The studio's tooltip and the CLI's refusal read as sentences: "1 segment", not "1 segments".
TEST(Cost, CountsOfOneAreSingular) {
    const Cost one = estimate_cost(grammar("axiom: F\n", 0), 0, false);
    ASSERT_EQ(one.modules, 1.0);
    ASSERT_EQ(one.segments, 1.0);
    EXPECT_EQ(cost_text(one).rfind("1 module, 1 segment, about ", 0), 0u) << cost_text(one);
    const Cost two = estimate_cost(grammar("axiom: FF\n", 0), 0, false);
    EXPECT_EQ(cost_text(two).rfind("2 modules, 2 segments, about ", 0), 0u) << cost_text(two);
}

// Resolutions of 1500 and more take gigabytes and minutes: over the default limits.
TEST(Cost, HighResolutionsAreOverTheDefaultLimits) {
    TreeTemplate t = default_template();
    t.params.drop_hidden = false;  // a trunk meshed at its own resolution, not for the budget
    t.params.branch_style = BranchStyle::Surface;  // meshed, not drawn
    for (int resolution : {1500, 2000}) {
        t.params.trunk_resolution = resolution;
        const Cost cost = estimate_cost(t, 800);
        EXPECT_GE(cost.cells, double(resolution) * resolution * resolution);
        EXPECT_FALSE(within(cost, {})) << cost_text(cost);
    }
}

// The limits must never refuse what ships: every built-in template at its own settings,
// with its budget and without.
TEST(Cost, EveryBuiltInTemplateIsWithinTheDefaultLimits) {
    for (const TreeTemplate* t : builtin_templates()) {
        for (std::size_t budget : {std::size_t(0), std::size_t(t->params.triangle_budget)}) {
            const Cost cost = estimate_cost(*t, budget);
            EXPECT_TRUE(within(cost, {})) << t->name << ": " << cost_text(cost);
            EXPECT_LT(cost.seconds, 3.0) << t->name << ": " << cost_text(cost);
        }
    }
}

// The ternary tree at generations 8, its trunk's surface reduced (branch_style = surface),
// crosses its branches many times, and each crossing makes
// the reduction slower than an estimate before any work can know. Once the meshes are made,
// their handles tell: over a 1-second limit there with every
// branch meshed, well within it at the template's own 6 generations, and within it too when
// the branches the crown hides are left out (drop_hidden, the template's own setting).
TEST(Cost, TheReductionIsEstimatedFromTheMeshesHandles) {
    TreeTemplate t = load_template("ternary");
    t.params.branch_style = BranchStyle::Surface;
    MeshOptions options;
    options.budget = 800;
    const Tree usual = generate_tree(t, options);
    const Cost usual_cost = estimate_reduction_cost(usual, 800);
    EXPECT_GT(usual_cost.handles, 50.0);
    CostLimits one_second;
    one_second.max_seconds = 1.0;
    EXPECT_TRUE(within(usual_cost, one_second)) << cost_text(usual_cost);
    EXPECT_EQ(estimate_reduction_cost(usual, 0).seconds, 0.0);

    t.params.blocks.edit<LSystemParams>().generations = 8;
    ASSERT_TRUE(t.params.drop_hidden);
    const Tree hidden = generate_tree(t, options);
    const Cost hidden_cost = estimate_reduction_cost(hidden, 800);
    EXPECT_TRUE(within(hidden_cost, one_second)) << cost_text(hidden_cost);

    t.params.drop_hidden = false;
    // A finer trunk grid than the template's 80 cells (which bind only above 1,422
    // triangles with drop_hidden): more handles.
    t.params.trunk_resolution = 96;
    // What the grammar alone can tell.
    EXPECT_TRUE(within(estimate_cost(t, 800), one_second)) << cost_text(estimate_cost(t, 800));
    const Tree crossed = generate_tree(t, options);
    const Cost cost = estimate_reduction_cost(crossed, 800);
    EXPECT_GT(cost.handles, 10 * usual_cost.handles);
    EXPECT_GT(cost.handles, 2 * hidden_cost.handles);
    EXPECT_FALSE(within(cost, one_second)) << cost_text(cost);
    EXPECT_NE(cost_text(cost).find("handles"), std::string::npos);
}

}  // namespace
// A job of many trees adds their time and keeps every finished tree: a batch of 1e9 trees is
// refused at once, however cheap each is.
TEST(Cost, ManyTreesAddUpTimeAndKeptMemory) {
    const TreeTemplate t = default_template();
    const Cost each = estimate_cost(t, 800);
    const Cost hundred = many_trees_cost(each, 100, 800);
    EXPECT_DOUBLE_EQ(hundred.seconds, 100 * each.seconds);
    EXPECT_GT(hundred.bytes, each.bytes);
    EXPECT_GT(many_trees_cost(each, 100, 0).bytes, hundred.bytes);  // raw meshes are kept
    EXPECT_TRUE(within(hundred, kManyTreeLimits));
    const Cost billion = many_trees_cost(each, 1e9, 800);
    EXPECT_FALSE(within(billion, kManyTreeLimits));
    try {
        check_cost(billion, kManyTreeLimits, "raise them", "this batch of 1e+09 trees");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("this batch of 1e+09 trees is estimated at"), std::string::npos)
            << message;
        EXPECT_NE(message.find("600 s"), std::string::npos) << message;
    }
}

// Space colonization's work is points x nodes: a million points that a tiny kill distance
// never lets die (tens of seconds) are refused before any growth, with the figures; the
// shipped colonization templates cost milliseconds.
TEST(Cost, ColonizationIsEstimatedFromItsPointsAndNodes) {
    TreeTemplate t = load_template("elm");
    const Cost usual = estimate_cost(t, 800);
    EXPECT_LT(usual.seconds, 1.0) << cost_text(usual);
    ColonizationParams& colonization = t.params.blocks.edit<ColonizationParams>();
    colonization.attraction_points = 1'000'000;
    colonization.kill_distance = 0.001;
    const Cost cost = estimate_cost(t, 800);
    EXPECT_GT(cost.seconds, 10.0) << cost_text(cost);
    EXPECT_GT(cost.segments, 1000.0) << cost_text(cost);
    try {
        check_cost(cost, {}, "raise --max-seconds");
        FAIL() << "accepted: " << cost_text(cost);
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("1000000 attraction points x about"), std::string::npos) << message;
    }
}

// Where the estimate is low, the growth's own count of its work holds the limits: it stops
// soon after passing them and says which and how to raise them.
TEST(Cost, AGrowthStopsAtItsLimitsWhateverTheEstimateSaid) {
    TreeTemplate t = load_template("elm");
    ColonizationParams& colonization = t.params.blocks.edit<ColonizationParams>();
    colonization.attraction_points = 5000;
    colonization.kill_distance = 0.01;
    GrowthContext context;
    context.limits = growth_limits({2e9, 0.01}, "raise --max-seconds");
    try {
        grow(t, context);
        FAIL() << "grew past its limit";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("space colonization grew 5000 attraction points x"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("over the limit of 2000 MB and 0.01 s"), std::string::npos)
            << message;
        EXPECT_NE(message.find("raise --max-seconds"), std::string::npos) << message;
    }
    EXPECT_NO_THROW(grow(t, GrowthContext{}));  // no limit: grows
}

}  // namespace sylva
