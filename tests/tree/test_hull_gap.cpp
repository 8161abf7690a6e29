// The gap a hull fills (tree/hull_gap.h): about nothing over a solid lump, about the sky
// between them over two lumps apart.
#include <gtest/gtest.h>

#include <vector>

#include "tree/hull_gap.h"

namespace sylva {
namespace {

// The points of a solid box's surface and inside, on a grid of `step`.
void add_block(std::vector<glm::vec3>& points, glm::vec3 lo, glm::vec3 hi, float step) {
    for (float x = lo.x; x <= hi.x + 1e-4f; x += step)
        for (float y = lo.y; y <= hi.y + 1e-4f; y += step)
            for (float z = lo.z; z <= hi.z + 1e-4f; z += step) points.emplace_back(x, y, z);
}

TEST(HullGap, ASolidLumpFillsNoGapAndTwoLumpsApartFillTheSkyBetween) {
    std::vector<glm::vec3> one;
    add_block(one, {0, 0, 0}, {1, 1, 1}, 0.05f);
    EXPECT_LT(hull_gap(one, 0.1f), 0.1);
    // A second lump 2 m above the first: from the side the hull adds about a 1 x 2 m band
    // between them (four views, the diagonal ones wider), from above nothing.
    std::vector<glm::vec3> two = one;
    add_block(two, {0, 3, 0}, {1, 4, 1}, 0.05f);
    const double gap = hull_gap(two, 0.1f);
    EXPECT_GT(gap, 4 * 2.0 * 0.9);
    EXPECT_LT(gap, 2 * 2.0 + 2 * 2.0 * 1.42 + 0.5);
    EXPECT_EQ(hull_gap(std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}}, 0.1f), 0.0);
}

}  // namespace
}  // namespace sylva
