// Turtle interpretation: endpoints follow the frame and formulas of docs/grammar.md.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "core/errors.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_parser.h"
#include "turtle/turtle.h"

namespace sylva {
namespace {

Skeleton draw(const std::string& axiom, TurtleSettings settings = {}) {
    DeriveSettings d;
    d.steps = 0;
    return interpret(derive(parse_lsystem("axiom: " + axiom), d), settings);
}

void expect_near(const glm::vec3& a, const glm::vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-5);
    EXPECT_NEAR(a.y, b.y, 1e-5);
    EXPECT_NEAR(a.z, b.z, 1e-5);
}

TEST(Turtle, TurnLeftThenForward) {
    Skeleton s = draw("F+(90)F");
    ASSERT_EQ(s.segments.size(), 2u);
    expect_near(s.segments[0].b, {0, 1, 0});
    expect_near(s.segments[1].b, {-1, 1, 0});
    EXPECT_EQ(s.segments[1].parent, 0);
}

TEST(Turtle, PitchAndRollFollowTheAbopFrame) {
    // & pitches H towards -U = (0,0,-1); ^ towards +U.
    expect_near(draw("&(90)F").segments[0].b, {0, 0, -1});
    expect_near(draw("^(90)F").segments[0].b, {0, 0, 1});
    // Rolling by 90 turns L into U, so a following left turn heads along +Z.
    expect_near(draw("\\(90)+(90)F").segments[0].b, {0, 0, 1});
    expect_near(draw("/(90)+(90)F").segments[0].b, {0, 0, -1});
    // | turns around.
    expect_near(draw("|F").segments[0].b, {0, -1, 0});
}

TEST(Turtle, DefaultAngleAndStepComeFromSettings) {
    TurtleSettings settings;
    settings.turn_angle = 90.0;
    settings.step = 2.0;
    expect_near(draw("F-F", settings).segments[1].b, {2, 2, 0});
}

TEST(Turtle, BranchesRestoreStateAndRecordDepthAndParent) {
    Skeleton s = draw("F[+(90)F]F");
    ASSERT_EQ(s.segments.size(), 3u);
    EXPECT_EQ(s.segments[1].depth, 1);
    EXPECT_EQ(s.segments[1].parent, 0);
    EXPECT_EQ(s.segments[2].depth, 0);
    EXPECT_EQ(s.segments[2].parent, 0);
    expect_near(s.segments[2].b, {0, 2, 0});
    EXPECT_EQ(tips(s), (std::vector<int>{1, 2}));
}

TEST(Turtle, MoveWithoutDrawing) {
    Skeleton s = draw("fF");
    ASSERT_EQ(s.segments.size(), 1u);
    expect_near(s.segments[0].a, {0, 1, 0});
}

TEST(Turtle, RollToVerticalLevelsTheLeftVector) {
    // After an arbitrary roll, $ brings L back to horizontal: a left turn then stays in
    // the horizontal plane of a heading that was tilted only by pitch.
    Skeleton s = draw("&(30)/(40)$+(90)F");
    glm::vec3 d = s.segments[0].b - s.segments[0].a;
    EXPECT_NEAR(d.y, 0.0, 1e-5);
    EXPECT_NEAR(glm::length(d), 1.0, 1e-5);
}

TEST(Turtle, TaperAndExplicitWidths) {
    TurtleSettings settings;
    settings.initial_width = 1.0;
    settings.trunk_taper = 0.5;
    settings.branch_taper = 0.25;
    Skeleton s = draw("FF[F]!(0.4)F", settings);
    EXPECT_FLOAT_EQ(s.segments[0].ra, 0.5f);
    EXPECT_FLOAT_EQ(s.segments[0].rb, 0.25f);
    EXPECT_FLOAT_EQ(s.segments[1].rb, 0.125f);
    EXPECT_FLOAT_EQ(s.segments[2].ra, 0.125f);    // the branch starts where it left
    EXPECT_FLOAT_EQ(s.segments[2].rb, 0.03125f);  // and tapers by branch_taper
    EXPECT_FLOAT_EQ(s.segments[3].ra, 0.2f);      // ! sets the width (a diameter)
}

TEST(Turtle, LptgModeMovesByElevationAndAzimuth) {
    TurtleSettings settings;
    settings.mode = TurtleMode::Lptg;
    settings.pitch_angle = 22.5;
    settings.turn_angle = 90.0;
    // Elevation starts horizontal: F heads along +X; four ^ of 22.5 point it up.
    expect_near(draw("F", settings).segments[0].b, {1, 0, 0});
    expect_near(draw("^^^^F", settings).segments[0].b, {0, 1, 0});
    expect_near(draw("+F", settings).segments[0].b, {0, 0, 1});
}

TEST(Turtle, PolygonsAndCut) {
    Skeleton s = draw("{.F.+(90)F.}[F%FFF]F");
    ASSERT_EQ(s.polygons.size(), 1u);
    EXPECT_EQ(s.polygons[0].size(), 3u);
    EXPECT_EQ(s.segments.size(), 4u);  // the cut drops FFF inside the branch
}

TEST(Turtle, UnbalancedBracketInTheWordIsAnError) {
    Word w;
    w.push('F');
    w.push(']');
    EXPECT_THROW(interpret(w, {}), GrammarError);
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

TEST(PipeModel, MurraysLawAtEveryFork) {
    TurtleSettings settings;
    settings.width_model = WidthModel::Pipe;
    settings.pipe_tip_width = 0.2;  // r0 = 0.1
    settings.pipe_exponent = 2.0;
    // Trunk, fork into two tips, one of which forks again.
    Skeleton s = draw("F[+F]F[+F]F", settings);
    ASSERT_EQ(s.segments.size(), 5u);
    const float r0 = 0.1f;
    EXPECT_FLOAT_EQ(s.segments[4].ra, r0);  // tips
    EXPECT_FLOAT_EQ(s.segments[3].ra, r0);
    EXPECT_FLOAT_EQ(s.segments[1].ra, r0);
    EXPECT_NEAR(s.segments[2].ra, std::sqrt(2.0f) * r0, 1e-6);  // r^2 = r0^2 + r0^2
    EXPECT_NEAR(s.segments[0].ra, std::sqrt(3.0f) * r0, 1e-6);
    EXPECT_NEAR(s.segments[0].rb, s.segments[2].ra, 1e-6);  // tapers to its thickest child
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

TEST(Tropism, BendsBranchesTowardsTheTropismVector) {
    TurtleSettings settings;
    settings.elasticity = 0.2;  // towards T = (0,-1,0), gravity
    Skeleton s = draw("+(90)FFFFFF", settings);
    ASSERT_EQ(s.segments.size(), 6u);
    float previous_slope = 0.0f;
    for (const Segment& seg : s.segments) {
        glm::vec3 d = glm::normalize(seg.b - seg.a);
        EXPECT_LT(d.y, previous_slope + 1e-6f) << "each segment points further down";
        previous_slope = d.y;
    }
    EXPECT_LT(previous_slope, -0.5f);
    // Without elasticity the branch stays horizontal.
    EXPECT_NEAR(draw("+(90)FFFFFF").segments.back().b.y, 0.0f, 1e-5);
}

}  // namespace
}  // namespace sylva
