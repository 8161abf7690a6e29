// The layout panel (ui/layout_panel.h) as ImGui frames without a window: it derives and grows
// on a worker while frames go on, shows the result, and planting a variation hands the forest
// preview a plan of the variation's polygons (by planting class) and switches the preview
// on; the preview's settings then plant that plan instead of the square.
#include <gtest/gtest.h>
#include <imgui.h>

#include <chrono>
#include <thread>

#include "tests/ui/headless_imgui.h"
#include "ui/layout_panel.h"
#include "ui/panels.h"
#include "ui/state/forest_preview_plan.h"

namespace sylva::studio {
namespace {

TEST(LayoutPanel, GrowsOnAWorkerAndPlantsAVariation) {
    HeadlessImGui imgui;
    LayoutPanelState panel;
    StudioState studio;
    studio.shown_template.name = "oak";
    EXPECT_FALSE(select_layout_example(panel, "no_such_example"));
    ASSERT_TRUE(select_layout_example(panel, "t_shape"));
    panel.count = 4;
    panel.size = 6;
    const PanelLayout layout = panel_layout(1280.0f, 800.0f);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!(panel.shown && panel.shown->source == "t_shape") &&
           std::chrono::steady_clock::now() < deadline) {
        ImGui::NewFrame();
        draw_layout_panel(panel, studio, layout);
        ImGui::Render();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_TRUE(panel.shown);
    ASSERT_TRUE(panel.shown->error.empty()) << panel.shown->error;
    ASSERT_EQ(panel.shown->variations.size(), 4u);
    for (const auto& v : panel.shown->report.items) EXPECT_EQ(v.size, 6);
    EXPECT_FALSE(studio.view.forest);
    ASSERT_TRUE(plant_layout(panel, studio));
    EXPECT_TRUE(studio.view.forest);
    ASSERT_TRUE(studio.view.forest_plan.ground);
    EXPECT_NE(studio.view.forest_plan.id, 0u);
    EXPECT_EQ(studio.view.forest_plan.ground->polygons.size(), 6u);
    // The preview plants the plan: its polygons, at 3 m per unit, centred; orchards too.
    const forest::ForestSettings s = forest_preview_settings(
        studio.shown_template, studio.view.forest_options, studio.view.forest_plan);
    EXPECT_EQ(s.ground.polygons.size(), 6u);
    EXPECT_TRUE(s.layout.has_value());
    EXPECT_EQ(s.species.size(), 2u);
    release_layout_panel(panel);
}

}  // namespace
}  // namespace sylva::studio
