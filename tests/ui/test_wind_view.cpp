// The studio's wind toggle, headless: the parts on screen sway with the exported wind data
// (the trunk's base stays, the crown moves), and --wind starts it frozen at a time.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <vector>

#include "tree/parameters.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"
#include "ui/state/studio_options.h"
#include "ui/state/studio_state.h"
#include "ui/state/wind_view.h"

namespace sylva::studio {
namespace {

TEST(WindView, TheBaseStaysWhileTheCrownSways) {
    const Tree tree = generate_tree(load_template("palm"));
    WindView view;
    set_wind_parts(view, tree.skeleton, tree.trunk, tree.crown, tree.leaves, tree.trunk, tree.crown,
                   tree.leaves);
    ASSERT_TRUE(view.ready);
    sway(view, 1.3f);
    const Mesh& rest = view.parts[0].rest;
    const Mesh& swayed = view.parts[0].swayed;
    ASSERT_EQ(rest.positions.size(), swayed.positions.size());
    const auto lowest = std::min_element(rest.positions.begin(), rest.positions.end(),
                                         [](auto& a, auto& b) { return a.y < b.y; }) -
                        rest.positions.begin();
    EXPECT_LT(glm::length(swayed.positions[lowest] - rest.positions[lowest]), 1e-3f);
    float moved = 0.0f;
    for (std::size_t part = 0; part < 3; ++part)
        for (std::size_t v = 0; v < view.parts[part].rest.positions.size(); ++v)
            moved = std::max(moved, glm::length(view.parts[part].swayed.positions[v] -
                                                view.parts[part].rest.positions[v]));
    EXPECT_GT(moved, 0.05f);
    EXPECT_LE(moved, wind_reach(view.motion));
}

TEST(WindView, WindOptionFreezesTheTime) {
    const char* args[] = {"sylva-studio", "--wind", "1.5"};
    EXPECT_EQ(parse_studio_options(3, args).wind_seconds, 1.5f);
    const char* none[] = {"sylva-studio"};
    EXPECT_FALSE(parse_studio_options(1, none).wind_seconds);
    const char* bad[] = {"sylva-studio", "--wind", "-1"};
    EXPECT_THROW(parse_studio_options(3, bad), UsageError);
}

// The View section's wind: no strength, no sway; a stronger wind moves the tree further, and
// the sway follows the direction set (mostly along z for a wind along z).
TEST(WindView, StrengthAndDirectionSetTheSway) {
    const Tree tree = generate_tree(load_template("palm"));
    auto farthest = [&](const WindMotion& motion) {
        WindView view;
        view.motion = motion;
        set_wind_parts(view, tree.skeleton, tree.trunk, tree.crown, tree.leaves, tree.trunk,
                       tree.crown, tree.leaves);
        glm::vec3 most(0.0f);
        for (float t : {0.4f, 1.3f, 2.2f}) {
            sway(view, t);
            for (const WindView::Part& part : view.parts)
                for (std::size_t v = 0; v < part.rest.positions.size(); ++v) {
                    const glm::vec3 d = part.swayed.positions[v] - part.rest.positions[v];
                    if (glm::length(d) > glm::length(most)) most = d;
                }
        }
        return most;
    };
    EXPECT_LT(glm::length(farthest({{1.0f, 0.0f}, 0.0f})), 1e-4f);
    const glm::vec3 weak = farthest({{1.0f, 0.0f}, 0.2f});
    const glm::vec3 strong = farthest({{1.0f, 0.0f}, 0.8f});
    EXPECT_GT(glm::length(strong), 2.0f * glm::length(weak));
    const glm::vec3 along_z = farthest({{0.0f, 1.0f}, 0.8f});
    EXPECT_GT(std::abs(along_z.z), std::abs(along_z.x));
    EXPECT_GT(std::abs(strong.x), std::abs(strong.z));
}

// The wind panel edits the template's wind: no regrowth (it moves the tree, it does not shape
// it), but an edit to save; the view sways in it, the same at the same time, the gusts
// making two times differ, flutter moving the leaves and not the trunk.
TEST(WindView, ThePanelsWindMovesTheViewWithoutRegrowing) {
    StudioState state;
    state.tree_template = load_template("palm");
    state.requested = state.tree_template;
    state.requested_budget = preview_budget(state);
    const TreeTemplate before = state.tree_template;
    set_param(state.tree_template.params, "wind_gust_frequency", 0.8);
    set_param(state.tree_template.params, "wind_flutter", 0.6);
    EXPECT_FALSE(edit_pending(state)) << "no new tree for a wind edit";
    EXPECT_FALSE(same_template(before, state.tree_template)) << "but an edit to save";

    const Tree tree = generate_tree(state.tree_template);
    WindView view;
    view.motion = wind_motion(state.tree_template.params);
    EXPECT_EQ(view.motion.gust_frequency, 0.8f);
    set_wind_parts(view, tree.skeleton, tree.trunk, tree.crown, tree.leaves, tree.trunk, tree.crown,
                   tree.leaves);
    auto at = [&](float t) {
        sway(view, t);
        return view.parts;
    };
    const auto first = at(2.0f);
    EXPECT_EQ(first[2].swayed.positions, at(2.0f)[2].swayed.positions) << "deterministic";
    const auto later = at(5.3f);
    float apart = 0.0f;
    for (std::size_t v = 0; v < first[0].swayed.positions.size(); ++v)
        apart = std::max(apart,
                         glm::length(first[0].swayed.positions[v] - later[0].swayed.positions[v]));
    EXPECT_GT(apart, 0.05f) << "the gusts lean the trunk differently at two times";
    // Flutter alone: the leaves move, the trunk (no flutter data) does not.
    auto flutter_moves = [&](std::size_t part) {
        WindView still = view, fluttering = view;
        still.motion.flutter = 0.0f;
        sway(still, 2.0f);
        sway(fluttering, 2.0f);
        float most = 0.0f;
        for (std::size_t v = 0; v < still.parts[part].rest.positions.size(); ++v)
            most = std::max(most, glm::length(still.parts[part].swayed.positions[v] -
                                              fluttering.parts[part].swayed.positions[v]));
        return most;
    };
    EXPECT_EQ(flutter_moves(0), 0.0f);
    EXPECT_GT(flutter_moves(2), 0.02f);
}

}  // namespace
}  // namespace sylva::studio
