// The growth-method seam: templates name their method, unknown names are clear errors, and
// the cancel flag reaches every stage of the pipeline.
#include <gtest/gtest.h>

#include <atomic>
#include <string>

#include "colonization/colonization_params.h"
#include "core/cancel.h"
#include "core/errors.h"
#include "tree/growth.h"
#include "tree/pipeline.h"
#include "tree/template_crown.h"
#include "tree/template_file.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

TEST(Growth, TheLSystemMethodIsRegisteredFirstAndFoundByName) {
    ASSERT_FALSE(growth_methods().empty());
    EXPECT_EQ(growth_methods().front()->name, "lsystem");
    for (const GrowthMethod* method : growth_methods()) {
        EXPECT_EQ(find_growth_method(method->name), method);
        EXPECT_FALSE(method->description.empty());
    }
    EXPECT_EQ(find_growth_method("no such method"), nullptr);
    EXPECT_EQ(default_template().growth, "lsystem");
}

TEST(Growth, GrowIsTheTemplatesMethod) {
    const TreeTemplate oak = default_template();
    std::vector<StageTime> times;
    const Skeleton s = grow(oak, {nullptr, &times});
    EXPECT_GT(s.segments.size(), 100u);
    ASSERT_EQ(times.size(), 2u);
    EXPECT_EQ(times[0].name, "derive");
    EXPECT_EQ(times[1].name, "turtle");
}

TEST(Growth, ColonizationTemplatesNeedNoGrammarAndGrowOneTree) {
    const TreeTemplate t = parse_template_file(
        "name = \"blob\"\ngrowth = \"colonization\"\n[params]\nenvelope = \"cone\"\n"
        "attraction_points = 500\n",
        "blob.toml");
    std::vector<StageTime> times;
    const Skeleton s = grow(t, {nullptr, &times});
    EXPECT_GT(tips(s).size(), 10u);
    for (size_t i = 0; i < s.segments.size(); ++i) EXPECT_LT(s.segments[i].parent, int(i));
    ASSERT_EQ(times.size(), 3u);
    EXPECT_EQ(times[1].name, "colonize");
    // Seeded: the same template grows the same skeleton.
    EXPECT_EQ(grow(t, {}).segments.back().b, s.segments.back().b);
    TreeTemplate bad = t;
    bad.params.blocks.edit<ColonizationParams>().kill_distance =
        colonization_params(bad.params).influence_radius + 1.0;
    EXPECT_THROW(grow(bad, {}), InputError);
}

TEST(Growth, EveryEnvelopeTemplateIsABuiltInTemplate) {
    for (std::string_view name : envelope_template_names())
        EXPECT_NO_THROW(load_template(std::string(name))) << name;
}

TEST(Growth, AColonizationCrownCanFillAnotherTemplatesCrown) {
    // The oak's crown as the pipeline builds it: the envelope's inside is field < 0.
    const TreeTemplate oak = load_template("oak");
    const TreeFields fields = tree_fields(grow(oak), oak.params);
    ASSERT_TRUE(fields.crown);
    const Region crown = template_crown("oak");
    EXPECT_EQ(crown.bounds.min, fields.crown_box.min);
    EXPECT_EQ(crown.bounds.max, fields.crown_box.max);
    const TreeTemplate t = parse_template_file(
        "name = \"in-oak\"\ngrowth = \"colonization\"\n[params]\nenvelope = \"template\"\n"
        "envelope_template = \"oak\"\nattraction_points = 1500\ntrunk_height = 1.0\n",
        "in-oak.toml");
    const Skeleton s = grow(t);
    EXPECT_GT(tips(s).size(), 20u);
    // The new tree's tips lie in or near the oak's crown (a kill distance away at most).
    int near = 0;
    for (int tip : tips(s)) near += (*fields.crown)(s.segments[size_t(tip)].b) < 0.5f;
    EXPECT_GT(near, int(tips(s).size() * 9 / 10));
    for (size_t i = 0; i < s.segments.size(); ++i) EXPECT_LT(s.segments[i].parent, int(i));
    EXPECT_THROW(template_crown("no such tree"), InputError);
}

TEST(Growth, AnUnknownMethodNamesTheKnownOnes) {
    TreeTemplate t = default_template();
    t.growth = "magic";
    try {
        grow(t);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("magic"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("lsystem"), std::string::npos) << e.what();
    }
}

TEST(Growth, TemplateFilesNameTheirMethodAndRejectUnknownOnes) {
    const std::string text = "name = \"t\"\ngrowth = \"lsystem\"\ngrammar = 'axiom: F'\n";
    EXPECT_EQ(parse_template_file(text, "t.toml").growth, "lsystem");
    try {
        parse_template_file("name = \"t\"\n\ngrowth = \"magic\"\ngrammar = 'axiom: F'\n", "t.toml");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where().source, "t.toml");
        EXPECT_EQ(e.line(), 3);
        EXPECT_NE(std::string(e.what()).find("lsystem"), std::string::npos) << e.what();
    }
}

TEST(Growth, TheGrammarsFirstLineIsFoundInTheFile) {
    EXPECT_EQ(parse_template_file("name = \"t\"\n\ngrammar = '''\naxiom: F\n'''\n", "t.toml")
                  .grammar_line,
              4);
    EXPECT_EQ(parse_template_file("name = \"t\"\ngrammar = 'axiom: F'\n", "t.toml").grammar_line,
              2);
    EXPECT_EQ(
        parse_template_file("name = \"t\"\ngrammar = '''axiom: F\n'''\n", "t.toml").grammar_line,
        2);
}

TEST(Cancel, ASetFlagStopsTheGrowthStage) {
    std::atomic<bool> cancel{true};
    MeshOptions options;
    options.cancel = &cancel;
    EXPECT_THROW(generate_tree(default_template(), options), Cancelled);
}

TEST(Cancel, AFlagSetWhileMeshingStopsThePipeline) {
    std::atomic<bool> cancel{false};
    MeshOptions options;
    options.cancel = &cancel;
    options.progress = [&cancel](float f) {
        if (f > 0.3f) cancel = true;
    };
    EXPECT_THROW(generate_tree(default_template(), options), Cancelled);
}

}  // namespace
}  // namespace sylva
