// Every file the studio's Save writes reopens in its Open and in `sylva -t FILE` (both
// load_template()): every built-in template, as a variant of the Variants strip (a seed of
// variant_seed(), jittered parameters), at the seed range's ends, and with each parameter and
// each #define constant at the ends of its range. Seeds stay in core/seed.h's range.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/seed.h"
#include "forest/variation.h"
#include "tree/grammar_constants.h"
#include "tree/parameters.h"
#include "tree/template_file.h"
#include "tree/template_library.h"
#include "tree/template_setting.h"

namespace {

using namespace sylva;
namespace fs = std::filesystem;

void expect_same(const TreeTemplate& back, const TreeTemplate& saved, const std::string& what) {
    SCOPED_TRACE(saved.name + " " + what);
    EXPECT_EQ(back.params.seed, saved.params.seed);
    EXPECT_EQ(back.grammar, saved.grammar);
    EXPECT_EQ(back.growth, saved.growth);
    for (const ParamInfo& info : param_infos())
        EXPECT_EQ(*get_param(back.params, info.key), *get_param(saved.params, info.key))
            << info.key;
    EXPECT_EQ(back.colors.trunk, saved.colors.trunk);
    EXPECT_EQ(back.colors.crown, saved.colors.crown);
    EXPECT_EQ(back.colors.leaves, saved.colors.leaves);
}

class SavedVariants : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sylva_saved_variants_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

// Save to a file as the studio does (its comments kept), then Open it as the studio and the
// CLI do.
TEST_F(SavedVariants, AVariantOfEveryTemplateSavesAndReopens) {
    for (const TreeTemplate* t : builtin_templates()) {
        const std::string original(builtin_template_text(t->name));
        std::vector<std::uint64_t> seeds = {0, kMaxSeed};
        // The strip's seeds for the largest base (the seed that could not be reopened came
        // from a variant) and for the default base.
        for (std::uint64_t i = 0; i < 3; ++i) {
            seeds.push_back(variant_seed(~std::uint64_t{0}, i));
            seeds.push_back(variant_seed(1, i));
        }
        for (const std::uint64_t seed : seeds) {
            ASSERT_TRUE(is_seed(seed)) << seed;
            TreeTemplate variant = *t;
            variant.params = varied_params(t->params, seed, 1.0);
            const fs::path file = dir_ / (t->name + ".toml");
            save_template_file(file, variant, original);
            expect_same(load_template(file.string()), variant, "seed " + std::to_string(seed));
        }
    }
}

// Each parameter at the ends of its range (each choice, each flag state) and each #define at
// the ends of its comment's range: the text Save writes reads back to the same template.
TEST(SavedSettings, EachParameterAndConstantAtItsEndsReadsBack) {
    for (const TreeTemplate* t : builtin_templates()) {
        const std::string original(builtin_template_text(t->name));
        auto round_trip = [&](const TreeTemplate& edited, const std::string& what) {
            expect_same(parse_template_file(template_file_text(edited, original), "saved.toml"),
                        edited, what);
        };
        for (const ParamInfo& info : param_infos()) {
            std::vector<double> values = {info.min, info.max};
            if (!info.choices.empty()) {
                values.clear();
                for (std::size_t c = 0; c < info.choices.size(); ++c)
                    values.push_back(static_cast<double>(c));
            }
            for (const double value : values) {
                TreeTemplate edited = *t;
                set_param(edited.params, info.key, value);
                round_trip(edited, std::string(info.key) + " = " + std::to_string(value));
            }
        }
        for (const GrammarDefine& d : grammar_defines(t->grammar)) {
            if (!d.min) continue;
            for (const double value : {*d.min, *d.max}) {
                TreeTemplate edited = *t;
                set_template_value(edited, d.name, value);
                round_trip(edited, "#define " + d.name + " " + std::to_string(value));
            }
        }
    }
}

}  // namespace
