// The parameter registry: every key of the shared table and of each growth method's table
// is read and written by key, ranges are checked with the key named, variation defaults
// change nothing, and a vector's keys and a flag's words read as before.
#include <gtest/gtest.h>

#include <string>

#include "colonization/colonization_params.h"
#include "core/errors.h"
#include "tree/parameters.h"
#include "turtle/lsystem_params.h"

namespace sylva {
namespace {

TEST(VariationParams, DefaultsChangeNothing) {
    const TreeParams p;
    EXPECT_EQ(p.age, 1.0);
    EXPECT_EQ(lsystem_params(p).bend, 0.0);
    EXPECT_EQ(lsystem_params(p).jitter, 0.0);
    EXPECT_EQ(lsystem_params(p).width_variation, 0.0);
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
    EXPECT_EQ(lsystem_params(p).bend, 30.0);
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

}  // namespace
}  // namespace sylva
