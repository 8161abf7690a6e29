// Colour variation per seed: 0 keeps the template's colours, crown and leaves shift together.
#include <gtest/gtest.h>

#include "core/color_variation.h"

namespace sylva {
namespace {

TEST(ColorVariation, ZeroKeepsTheColoursAndSeedsDiffer) {
    const PartColors base;
    const PartColors same = varied_colors(base, 0.0, 99);
    EXPECT_EQ(same.trunk, base.trunk);
    EXPECT_EQ(same.crown, base.crown);
    const PartColors a = varied_colors(base, 0.8, 1), b = varied_colors(base, 0.8, 2);
    EXPECT_NE(a.crown, b.crown);
    EXPECT_EQ(a.crown, varied_colors(base, 0.8, 1).crown);
    for (const glm::vec3& c : {a.trunk, a.crown, a.leaves, b.trunk, b.crown, b.leaves})
        for (int i = 0; i < 3; ++i) {
            EXPECT_GE(c[i], 0.0f);
            EXPECT_LE(c[i], 1.0f);
        }
    // Crown and leaves shift by the same factors, so they stay matched.
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(a.crown[i] / base.crown[i], a.leaves[i] / base.leaves[i], 1e-5);
}

}  // namespace
}  // namespace sylva
