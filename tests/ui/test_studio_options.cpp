// sylva-studio's command line: the screenshot mode scripts and tests rely on.
#include <gtest/gtest.h>

#include <vector>

#include "ui/state/studio_options.h"

namespace sylva::studio {
namespace {

StudioOptions parse(std::vector<const char*> args) {
    args.insert(args.begin(), "sylva-studio");
    return parse_studio_options(static_cast<int>(args.size()), args.data());
}

TEST(StudioOptions, DefaultsOpenTheDefaultTreeInAWindow) {
    StudioOptions o = parse({});
    EXPECT_FALSE(o.screenshot_path);
    EXPECT_EQ(o.tree_template, "default");
    EXPECT_FALSE(o.low_poly);
}

TEST(StudioOptions, ScreenshotWithTemplateAndFrames) {
    StudioOptions o = parse({"--screenshot", "out.png", "--template", "spruce", "--frames", "3"});
    ASSERT_TRUE(o.screenshot_path);
    EXPECT_EQ(*o.screenshot_path, "out.png");
    EXPECT_EQ(o.tree_template, "spruce");
    EXPECT_EQ(o.screenshot_frames, 3);
    EXPECT_EQ(parse({"-t", "my.toml"}).tree_template, "my.toml");
}

TEST(StudioOptions, LodPicksALevelOfTheLowPolyView) {
    StudioOptions o = parse({"--lod", "3"});
    EXPECT_TRUE(o.low_poly);
    EXPECT_EQ(o.lod_level, 3);
    EXPECT_EQ(parse({"--low-poly"}).lod_level, 0);
    EXPECT_THROW(parse({"--lod", "4"}), UsageError);
    EXPECT_THROW(parse({"--lod", "-1"}), UsageError);
    EXPECT_THROW(parse({"--lod"}), UsageError);
}

TEST(StudioOptions, ColonizationOverlays) {
    StudioOptions o = parse({});
    EXPECT_TRUE(o.envelope);
    EXPECT_FALSE(o.points);
    EXPECT_FALSE(o.replay_iteration);
    o = parse({"--no-envelope", "--points", "--replay", "12"});
    EXPECT_FALSE(o.envelope);
    EXPECT_TRUE(o.points);
    ASSERT_TRUE(o.replay_iteration);
    EXPECT_EQ(*o.replay_iteration, 12);
    EXPECT_THROW(parse({"--replay", "-1"}), UsageError);
    EXPECT_THROW(parse({"--replay", "x"}), UsageError);
    EXPECT_THROW(parse({"--replay"}), UsageError);
}

TEST(StudioOptions, LayoutOpensThePanelOnAnExample) {
    EXPECT_FALSE(parse({}).layout_example);
    StudioOptions o = parse({"--layout", "village"});
    ASSERT_TRUE(o.layout_example);
    EXPECT_EQ(*o.layout_example, "village");
    EXPECT_THROW(parse({"--layout"}), UsageError);
    EXPECT_THROW(parse({"--layout", ""}), UsageError);
}

TEST(StudioOptions, RejectsMistakesWithAUsageError) {
    EXPECT_THROW(parse({"--frames", "3"}), UsageError);  // without --screenshot
    EXPECT_THROW(parse({"--screenshot", "a.png", "--frames", "0"}), UsageError);
    EXPECT_THROW(parse({"--screenshot", "a.png", "--frames", "x"}), UsageError);
    EXPECT_THROW(parse({"--screenshot"}), UsageError);
    EXPECT_THROW(parse({"--template"}), UsageError);
    EXPECT_THROW(parse({"--bogus"}), UsageError);
}

TEST(StudioOptions, VariantsStripCount) {
    EXPECT_EQ(parse({}).variants, 0);
    EXPECT_EQ(parse({"--variants", "6"}).variants, 6);
    for (const char* bad : {"0", "13", "x", "-1"})
        EXPECT_THROW(parse({"--variants", bad}), UsageError) << bad;
}

}  // namespace
}  // namespace sylva::studio
