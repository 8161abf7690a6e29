// Built-in templates grow what they promise.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <set>

#include "core/mesh_checks.h"
#include "tree/growth.h"
#include "tree/parameters.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

TEST(Spruce, VerticalTrunkWithWhorlsOfDroopingBranches) {
    Skeleton s = grow(load_template("seed_spruce"));
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

namespace sylva {
namespace {

// A fingerprint of everything generate_tree produces.
std::vector<float> fingerprint(const Tree& tree) {
    std::vector<float> out;
    for (const Mesh* mesh : {&tree.trunk, &tree.crown, &tree.leaves}) {
        out.push_back(static_cast<float>(mesh->triangles.size()));
        for (const glm::vec3& p : mesh->positions) out.insert(out.end(), {p.x, p.y, p.z});
    }
    return out;
}

TEST(Sliders, EverySeed001ParameterChangesTheSpruce) {
    TreeTemplate spruce = load_template("seed_spruce");
    spruce.params.trunk_resolution = spruce.params.crown_resolution = 24;
    const std::vector<float> base = fingerprint(generate_tree(spruce));
    const char* keys[] = {"trunk_resolution", "crown_resolution", "branch_length",   "branch_width",
                          "trunk_taper",      "branch_taper",     "sphere_diameter", "crown_offset",
                          "crown_fusion",     "generations",      "pitch_angle",     "yaw_angle"};
    for (const char* key : keys) {
        TreeTemplate changed = spruce;
        double value = *get_param(changed.params, key);
        const ParamInfo* info = nullptr;
        for (const ParamInfo& i : param_infos())
            if (i.key == key) info = &i;
        ASSERT_NE(info, nullptr) << key;
        // A step inside the range: up by 20% (at least 1 for whole numbers), else down.
        double step = info->integer ? std::max(1.0, std::round(value * 0.2)) : value * 0.2;
        double next = value + step <= info->max ? value + step : value - step;
        set_param(changed.params, key, next);
        EXPECT_NE(fingerprint(generate_tree(changed)), base)
            << key << " " << value << " -> " << next;
    }
}

}  // namespace
}  // namespace sylva
