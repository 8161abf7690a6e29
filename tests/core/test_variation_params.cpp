// The variation and age parameters: defaults that change nothing, ranges checked with the
// key named, and colour variation per seed (crown and leaves shifted together).
#include <gtest/gtest.h>

#include <string>

#include "core/color_variation.h"
#include "core/errors.h"
#include "core/tree_params.h"

namespace sylva {
namespace {

TEST(VariationParams, DefaultsChangeNothing) {
    const TreeParams p;
    EXPECT_EQ(p.age, 1.0);
    EXPECT_EQ(p.bend, 0.0);
    EXPECT_EQ(p.jitter, 0.0);
    EXPECT_EQ(p.width_variation, 0.0);
    EXPECT_EQ(p.tropism_variation, 0.0);
    EXPECT_EQ(p.color_variation, 0.0);
}

TEST(VariationParams, OutOfRangeValuesNameTheKey) {
    const std::pair<const char*, const char*> bad[] = {{"age", "1.5"},
                                                       {"age", "-0.1"},
                                                       {"bend", "400"},
                                                       {"jitter", "1"},
                                                       {"bend_frequency", "0"},
                                                       {"width_variation", "nan"},
                                                       {"tropism_variation", "3"},
                                                       {"color_variation", "2"}};
    for (const auto& [key, value] : bad) {
        TreeParams p;
        try {
            set_param(p, key, value);
            ADD_FAILURE() << key << "=" << value;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
        }
    }
    TreeParams p;
    set_param(p, "age", "0.25");
    set_param(p, "bend", "30");
    EXPECT_EQ(p.age, 0.25);
    EXPECT_EQ(p.bend, 30.0);
}

// The value in a refusal reads back as what was given: "not 10" for 10.0000000001 would
// say nothing.
TEST(VariationParams, ARefusedValueIsShownAsGiven) {
    TreeParams p;
    try {
        set_param(p, "generations", 10.0000000001);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("not 10.0000000001"), std::string::npos) << e.what();
    }
    try {
        set_param(p, "age", 1.0000001);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("= 1.0000001 is out of range"), std::string::npos)
            << e.what();
    }
}

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
