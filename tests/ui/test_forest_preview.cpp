// The forest preview's planting (ui/state/forest_preview_plan.h): the square the studio shows is
// planted inside its bounds, with K variants of the edited template, the same for a seed.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <glm/ext/matrix_transform.hpp>

#include "core/cancel.h"
#include "tree/template_library.h"
#include "ui/state/forest_export.h"
#include "ui/state/forest_preview_plan.h"
#include "ui/state/studio_options.h"

namespace sylva::studio {
namespace {

TEST(ForestPreview, PlantsTreesInsideTheSquare) {
    const TreeTemplate oak = load_template("oak");
    for (float size : {20.0f, 40.0f, 100.0f}) {
        const forest::ForestPlan plan = plan_forest_preview(oak, {size, 4});
        ASSERT_GT(plan.placements.size(), 0u) << size;
        for (const forest::Placement& p : plan.placements) {
            EXPECT_LE(std::abs(p.position.x), 0.5 * size) << size;
            EXPECT_LE(std::abs(p.position.z), 0.5 * size) << size;
            EXPECT_EQ(p.position.y, 0.0);
            EXPECT_LT(p.variant, plan.variants.size());
        }
    }
}

TEST(ForestPreview, UsesTheTemplateAsItsOnlySpeciesWithKVariants) {
    TreeTemplate oak = load_template("oak");
    oak.params.seed = 7;
    const forest::ForestSettings s = forest_preview_settings(oak, {40.0f, 3});
    ASSERT_EQ(s.species.size(), 1u);
    EXPECT_EQ(s.species[0].tree.name, oak.name);
    EXPECT_EQ(s.seed, 7u);
    EXPECT_EQ(s.finish.budget.total, kForestPreviewBudget);
    const forest::ForestPlan plan = plan_forest_preview(oak, {40.0f, 3});
    EXPECT_EQ(plan.variants.size(), 3u);
    // Out-of-range options are clamped to the sliders' ranges, not refused.
    EXPECT_EQ(forest_preview_settings(oak, {40.0f, 99}).variants,
              static_cast<std::size_t>(kForestPreviewMaxVariants));
    EXPECT_LE(plan_forest_preview(oak, {5.0f, 4}).placements.size(),
              plan_forest_preview(oak, {kForestPreviewMinSize, 4}).placements.size());
}

TEST(ForestPreview, IsDeterministicForASeedAndChangesWithIt) {
    TreeTemplate oak = load_template("oak");
    const forest::ForestPlan a = plan_forest_preview(oak, {});
    const forest::ForestPlan b = plan_forest_preview(oak, {});
    ASSERT_EQ(a.placements.size(), b.placements.size());
    for (std::size_t i = 0; i < a.placements.size(); ++i) {
        EXPECT_EQ(a.placements[i].position, b.placements[i].position);
        EXPECT_EQ(a.placements[i].variant, b.placements[i].variant);
        EXPECT_EQ(a.placements[i].yaw_degrees, b.placements[i].yaw_degrees);
    }
    oak.params.seed += 1;
    const forest::ForestPlan c = plan_forest_preview(oak, {});
    bool moved = c.placements.size() != a.placements.size();
    for (std::size_t i = 0; !moved && i < a.placements.size(); ++i)
        moved = c.placements[i].position != a.placements[i].position;
    EXPECT_TRUE(moved);
}

TEST(ForestPreview, AGreaterSquareHoldsMoreTrees) {
    const TreeTemplate oak = load_template("oak");
    EXPECT_GT(plan_forest_preview(oak, {80.0f, 4}).placements.size(),
              2 * plan_forest_preview(oak, {40.0f, 4}).placements.size());
}

TEST(ForestPreview, AppendTransformedPlacesAndReindexes) {
    Mesh triangle;
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    triangle.triangles = {{0, 1, 2}};
    Mesh into;
    append_transformed(into, triangle, glm::mat4(1.0f));
    const glm::mat4 model =
        glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, -5)),
                               glm::radians(90.0f), glm::vec3(0, 1, 0)),
                   glm::vec3(2.0f));
    append_transformed(into, triangle, model);
    ASSERT_EQ(into.positions.size(), 6u);
    ASSERT_EQ(into.triangles.size(), 2u);
    EXPECT_EQ(into.triangles[1], (std::array<std::uint32_t, 3>{3, 4, 5}));
    EXPECT_NEAR(into.positions[3].x, 10.0f, 1e-5f);
    EXPECT_NEAR(into.positions[3].z, -5.0f, 1e-5f);
    // (1, 0, 0) turned 90 degrees about +Y is (0, 0, -1), then doubled.
    EXPECT_NEAR(into.positions[4].x, 10.0f, 1e-5f);
    EXPECT_NEAR(into.positions[4].z, -7.0f, 1e-5f);
    EXPECT_NEAR(into.positions[5].y, 2.0f, 1e-5f);
}

TEST(ForestPreview, ACancelledPreviewStops) {
    const std::atomic<bool> cancel{true};
    EXPECT_THROW(make_forest_preview(load_template("oak"), {}, &cancel), Cancelled);
}

TEST(ForestPreview, TheOptionTurnsItOn) {
    const char* off[] = {"sylva-studio"};
    EXPECT_FALSE(parse_studio_options(1, off).forest_preview);
    const char* on[] = {"sylva-studio", "--forest-preview"};
    EXPECT_TRUE(parse_studio_options(2, on).forest_preview);
}

// File > Export forest writes the preview's square as sylva forest does, into a folder that
// did not exist yet, beside the tree's export path.
TEST(ForestPreview, ExportsTheSquareWithItsPlacements) {
    EXPECT_EQ(forest_export_path("out/tree.glb"), std::filesystem::path("out/tree_forest.glb"));
    TreeTemplate t = load_template("default");
    t.params.triangle_budget = 200;
    const auto dir = std::filesystem::temp_directory_path() / "sylva_forest_export_test";
    std::filesystem::remove_all(dir);
    const auto glb = dir / "new" / "tree_forest.glb";
    const std::string message = export_forest(t, {20.0f, 1}, glb);
    EXPECT_NE(message.find("trees"), std::string::npos) << message;
    EXPECT_GT(std::filesystem::file_size(glb), 1000u);
    EXPECT_TRUE(std::filesystem::exists(forest::placements_csv_path(glb)));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sylva::studio
