// Grammar files: what is written reads back byte for byte; bad indices, versions and
// numbers are refused naming the key.
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "layout/grammar_json.h"
#include "layout_test_helpers.h"

namespace sylva::layout {
namespace {

using testing::grammar_of;

std::string error_of(const std::string& json) {
    try {
        read_grammar_json(json, "g.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(LayoutGrammarJson, RoundTripsAndRefusesBadIndices) {
    const Grammar& g = grammar_of("t_shape");
    const std::string json = write_grammar_json(g);
    const Grammar back = read_grammar_json(json, "t.json");
    EXPECT_EQ(write_grammar_json(back), json);
    EXPECT_EQ(back.dirs.label_length, g.dirs.label_length);
    EXPECT_EQ(back.hierarchy.stopped_by, g.hierarchy.stopped_by);
    std::string bad = json;
    const std::size_t at = bad.find("\"starters\"");
    ASSERT_NE(at, std::string::npos);
    bad.replace(bad.find("[", bad.find("[", at) + 1) + 1, 0, "[[99,0,-1]],");
    EXPECT_NE(error_of(bad).find("starters[0]"), std::string::npos) << error_of(bad);
    EXPECT_THROW(read_grammar_json("{\"format\": 3}"), InputError);
}

TEST(LayoutGrammarJson, RefusesOtherVersionsAndOutOfRangeNumbers) {
    const nlohmann::json doc = nlohmann::json::parse(write_grammar_json(grammar_of("l_shape")));
    nlohmann::json v1 = doc;
    v1["version"] = 1;
    EXPECT_NE(error_of(v1.dump()).find("version"), std::string::npos);
    // 2^64 - 1 as a vertex index is not -1 (unsigned JSON numbers are compared unsigned).
    nlohmann::json huge = doc;
    huge["starters"][0][0][0][2] = std::numeric_limits<std::uint64_t>::max();
    EXPECT_NE(error_of(huge.dump()).find("starters[0][0][0]"), std::string::npos)
        << error_of(huge.dump());
    nlohmann::json negative = doc;
    negative["label_length"][0][3] = -5;
    EXPECT_NE(error_of(negative.dump()).find("label_length[0]"), std::string::npos);
    nlohmann::json pieces = doc;
    ASSERT_FALSE(pieces["rules"].empty());
    for (int k = 0; k < 40; ++k)
        pieces["rules"][0]["right"].push_back(pieces["rules"][0]["right"][0]);
    EXPECT_NE(error_of(pieces.dump()).find("rules[0].right"), std::string::npos);
}

}  // namespace
}  // namespace sylva::layout
