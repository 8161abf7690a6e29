// The studio's wind toggle, headless: the parts on screen sway with the exported wind data
// (the trunk's base stays, the crown moves), and --wind starts it frozen at a time.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <vector>

#include "tree/pipeline.h"
#include "tree/template_library.h"
#include "ui/state/studio_options.h"
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
    EXPECT_LE(moved, 1.5f * view.motion.strength);
}

TEST(WindView, WindOptionFreezesTheTime) {
    const char* args[] = {"sylva-studio", "--wind", "1.5"};
    EXPECT_EQ(parse_studio_options(3, args).wind_seconds, 1.5f);
    const char* none[] = {"sylva-studio"};
    EXPECT_FALSE(parse_studio_options(1, none).wind_seconds);
    const char* bad[] = {"sylva-studio", "--wind", "-1"};
    EXPECT_THROW(parse_studio_options(3, bad), UsageError);
}

}  // namespace
}  // namespace sylva::studio
