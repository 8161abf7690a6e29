// Built-in templates grow what they promise.
#include "app/pipeline.h"
#include "app/template_library.h"
#include "marching/mesh_checks.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <set>

namespace sylva {
namespace {

TEST(Spruce, VerticalTrunkWithWhorlsOfDroopingBranches) {
    Skeleton s = grow_skeleton(load_template("spruce"));
    int trunk = 0;
    for (const Segment& seg : s.segments) {
        if (seg.depth != 0) continue;
        ++trunk;
        glm::vec3 d = glm::normalize(seg.b - seg.a);
        EXPECT_NEAR(d.y, 1.0f, 1e-5) << "trunk segments point straight up";
    }
    EXPECT_EQ(trunk, 4 + 3 * 5);  // P gives 4 F, then M adds 3 in each of 5 more steps

    // Whorls: branches leave the trunk in groups of five at one height, pointing below the
    // horizontal, at five different azimuths.
    std::map<float, std::vector<glm::vec3>> whorls;  // height -> first-segment directions
    for (const Segment& seg : s.segments) {
        if (seg.depth != 1 || seg.parent < 0) continue;
        if (s.segments[static_cast<size_t>(seg.parent)].depth != 0) continue;
        whorls[std::round(seg.a.y * 1000.0f) / 1000.0f].push_back(glm::normalize(seg.b - seg.a));
    }
    ASSERT_GE(whorls.size(), 4u);
    for (const auto& [height, directions] : whorls) {
        EXPECT_EQ(directions.size(), 5u) << "at height " << height;
        std::set<int> azimuths;
        for (const glm::vec3& d : directions) {
            EXPECT_LT(d.y, 0.0f) << "branches droop";
            azimuths.insert(static_cast<int>(std::lround(std::atan2(d.z, d.x) * 180 / 3.14159265)));
        }
        EXPECT_EQ(azimuths.size(), directions.size()) << "spread around the trunk";
    }
}

TEST(Templates, EveryBuiltInExportsAClosedTrunk) {
    for (const TreeTemplate* t : builtin_templates()) {
        Tree tree = generate_tree(*t);
        EXPECT_GT(tree.trunk.triangles.size(), 100u) << t->name;
        EXPECT_TRUE(check_topology(tree.trunk).is_closed_manifold()) << t->name;
        EXPECT_FALSE(t->description.empty()) << t->name;
    }
}

}  // namespace
}  // namespace sylva
