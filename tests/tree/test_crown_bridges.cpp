// The struts that join a low budget's crown blobs (tree/crown_bridges.h): as thick as their
// spheres where they are short, so the gaps between blobs stay open; none for a sparse crown
// (slender struts) from 200 triangles on; a cell thick where the budget joins the whole crown.
#include <gtest/gtest.h>

#include <vector>

#include "core/box.h"
#include "core/tree_params.h"
#include "sdf/sphere_field.h"
#include "tree/crown_bridges.h"

namespace sylva {
namespace {

// 40 spheres of `radius` on a line, `spacing` apart, in a box meshed with 0.3 cells.
struct Row {
    SphereField field;
    Box box;
    TreeParams params;
};
Row row_of(float radius, float spacing) {
    std::vector<Ball> balls;
    for (int i = 0; i < 40; ++i)
        balls.push_back({glm::vec3(spacing * static_cast<float>(i), 0.0f, 0.0f), radius});
    Row row{SphereField(balls, 0.0f, 1.0f), {}, {}};
    row.box.min = glm::vec3(-1.0f);
    row.box.max = glm::vec3(-1.0f) + glm::vec3(30.0f * 0.3f);
    row.params.crown_merge = true;
    row.params.crown_resolution = 30;  // cells of 0.3
    return row;
}

TEST(CrownBridges, ShortStrutsAreAsThickAsTheirSpheres) {
    // Spheres of 0.2 (two thirds of a cell) 0.5 apart: 40 pieces are too many for 400
    // triangles, which join them into 8.
    const Row row = row_of(0.2f, 0.5f);
    const std::vector<CappedCone> struts = crown_bridge_cones(row.field, 400, row.params, row.box);
    ASSERT_FALSE(struts.empty());
    for (const CappedCone& c : struts) {
        EXPECT_FLOAT_EQ(c.ra, 0.2f);
        EXPECT_FLOAT_EQ(c.rb, 0.2f);
    }
    // Spheres thinner than half a cell get half a cell.
    for (const CappedCone& c :
         crown_bridge_cones(row_of(0.1f, 0.35f).field, 400, row.params, row.box))
        EXPECT_FLOAT_EQ(c.ra, 0.15f);
}

// Spheres of 0.2 1.2 apart (struts six radii long) are a sparse crown: from 200 triangles on
// its blobs stay apart, below its struts are a cell thick, as are those that join a whole
// crown into a few pieces.
TEST(CrownBridges, ASparseCrownStaysApartAndAWholeCrownJoinedIsACellThick) {
    const Row slender = row_of(0.2f, 1.2f);
    EXPECT_TRUE(crown_bridge_cones(slender.field, 400, slender.params, slender.box).empty());
    EXPECT_TRUE(crown_bridge_cones(slender.field, 200, slender.params, slender.box).empty());
    EXPECT_TRUE(keeps_sparse_crown_apart(200));
    EXPECT_FALSE(keeps_sparse_crown_apart(150));
    const std::vector<CappedCone> struts =
        crown_bridge_cones(slender.field, 150, slender.params, slender.box);
    ASSERT_FALSE(struts.empty());
    for (const CappedCone& c : struts) EXPECT_FLOAT_EQ(c.ra, 0.3f);
    // 100 triangles join the short struts' row into two pieces.
    const Row joined = row_of(0.2f, 0.5f);
    const std::vector<CappedCone> few =
        crown_bridge_cones(joined.field, 100, joined.params, joined.box);
    ASSERT_FALSE(few.empty());
    for (const CappedCone& c : few) EXPECT_FLOAT_EQ(c.ra, 0.3f);
}

}  // namespace
}  // namespace sylva
