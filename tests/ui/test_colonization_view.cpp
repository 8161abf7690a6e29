// The studio's space colonization items without a window: the growth-method switch as an
// undoable edit, the envelope's wire, the attraction points shown, and growth replayed step
// by step.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <glm/geometric.hpp>
#include <thread>
#include <vector>

#include "colonization/branch_shaping.h"
#include "colonization/colonization_growth.h"
#include "tree/growth.h"
#include "tree/template_library.h"
#include "ui/state/colonization_view.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {
namespace {

TEST(ColonizationView, GrowthSwitchIsAnUndoableEdit) {
    StudioState state;
    state.tree_template = state.committed = load_template("default");
    ASSERT_EQ(state.tree_template.growth, "lsystem");
    ASSERT_FALSE(grows_by_colonization(state.tree_template));
    state.requested = state.tree_template;  // as if its tree were generated

    set_growth_method(state, "colonization");
    EXPECT_EQ(state.tree_template.growth, "colonization");
    EXPECT_TRUE(grows_by_colonization(state.tree_template));
    EXPECT_EQ(state.undo.size(), 1u);
    EXPECT_TRUE(edit_pending(state));  // live mode regenerates with the other method

    undo(state);
    EXPECT_EQ(state.tree_template.growth, "lsystem");
    redo(state);
    EXPECT_EQ(state.tree_template.growth, "colonization");
    // undo and redo started generations: stop them before the state goes.
    cancel_generations(state);
    while (generation_running(state) || !state.stale.empty()) {
        poll_jobs(state);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

TEST(ColonizationView, EveryBuiltInMethodIsOffered) {
    // The combo lists growth_methods(); the switch must accept each by name.
    for (const GrowthMethod* method : growth_methods()) {
        StudioState state;
        state.tree_template = state.committed = load_template("default");
        set_growth_method(state, method->name);
        EXPECT_EQ(state.tree_template.growth, method->name);
    }
}

// The envelope's centre: strictly inside every shape, all of which are convex.
glm::vec3 centre(const Envelope& e) {
    const Box box = bounds(e);
    return 0.5f * (box.min + box.max);
}

TEST(ColonizationView, EnvelopeWireLiesOnTheBoundary) {
    for (EnvelopeShape shape :
         {EnvelopeShape::Sphere, EnvelopeShape::Ellipsoid, EnvelopeShape::Cone,
          EnvelopeShape::Cylinder, EnvelopeShape::Hemisphere}) {
        Envelope e;
        e.shape = shape;
        e.size = {7.0f, 4.0f, 5.0f};
        e.base = {1.0f, 2.5f, -0.5f};
        const std::vector<glm::vec3> wire = envelope_wire(e);
        ASSERT_FALSE(wire.empty());
        ASSERT_EQ(wire.size() % 2, 0u);  // line pairs
        const glm::vec3 c = centre(e);
        ASSERT_TRUE(inside(e, c));
        for (const glm::vec3& p : wire) {
            // On the boundary: a hair towards the centre is inside, a hair away is not.
            EXPECT_TRUE(inside(e, c + 0.999f * (p - c))) << static_cast<int>(shape);
            EXPECT_FALSE(inside(e, c + 1.001f * (p - c))) << static_cast<int>(shape);
        }
        // The cage spans the envelope: its points reach the bounds' top and bottom.
        const Box box = bounds(e);
        float low = wire.front().y, high = wire.front().y;
        for (const glm::vec3& p : wire) low = std::min(low, p.y), high = std::max(high, p.y);
        EXPECT_NEAR(low, box.min.y, 1e-4f);
        EXPECT_NEAR(high, box.max.y, 1e-4f);
    }
}

TEST(ColonizationView, TemplateEnvelopeWireFollowsItsParameters) {
    TreeTemplate elm = load_template("elm");
    const std::vector<glm::vec3> wire = template_envelope_wire(elm);
    const Envelope e = template_envelope(colonization_params(elm.params));
    const glm::vec3 c = centre(e);
    for (const glm::vec3& p : wire) EXPECT_TRUE(inside(e, c + 0.999f * (p - c)));
    elm.params.blocks.edit<ColonizationParams>().envelope_size.x *= 2.0;
    EXPECT_NE(template_envelope_wire(elm), wire);
}

// The skeleton colonization_growth makes from `points`: its own steps after placement.
Skeleton grow_from(const std::vector<glm::vec3>& points, const TreeParams& p) {
    ColonizationGraph graph = colonize(points, glm::vec3(0.0f), colonization_settings(p));
    draw_successors_together(graph, static_cast<float>(colonization_params(p).angle_smoothing));
    reduce_curves(graph, static_cast<float>(colonization_params(p).curve_reduction));
    return to_skeleton(graph, static_cast<float>(0.5 * p.tip_width),
                       static_cast<float>(p.pipe_exponent));
}

TEST(ColonizationView, PointsShownAreTheGrowthsPoints) {
    TreeTemplate elm = load_template("elm");
    elm.params.blocks.edit<ColonizationParams>().attraction_points = 500;  // small and quick
    const std::vector<glm::vec3> shown = template_attraction_points(elm);
    ASSERT_EQ(shown.size(), 500u);
    const Envelope e = template_envelope(colonization_params(elm.params));
    for (const glm::vec3& p : shown) EXPECT_TRUE(inside(e, p));
    // Grown from the points shown, the tree is the growth method's own, point for point.
    const Skeleton expected = grow(elm);
    const Skeleton from_shown = grow_from(shown, elm.params);
    ASSERT_EQ(from_shown.segments.size(), expected.segments.size());
    for (std::size_t i = 0; i < expected.segments.size(); ++i) {
        EXPECT_EQ(from_shown.segments[i].a, expected.segments[i].a);
        EXPECT_EQ(from_shown.segments[i].b, expected.segments[i].b);
    }
    // Another seed, other points; the same seed, the same points.
    TreeTemplate other = elm;
    other.params.seed += 1;
    EXPECT_NE(template_attraction_points(other), shown);
    EXPECT_EQ(template_attraction_points(elm), shown);
}

TEST(ColonizationView, ReplayedPointsDieStepByStep) {
    TreeTemplate elm = load_template("elm");
    const std::vector<glm::vec3> all = template_attraction_points(elm);
    const int last = last_iteration(grow(elm));
    std::size_t before = all.size();
    for (int step = 0; step <= last; step += 3) {
        const std::vector<glm::vec3> alive = attraction_points_alive(elm, step);
        EXPECT_LE(alive.size(), before) << "step " << step;
        before = alive.size();
        for (const glm::vec3& p : alive)
            EXPECT_NE(std::find(all.begin(), all.end(), p), all.end());  // some of the shown
    }
    EXPECT_LT(attraction_points_alive(elm, last).size(), all.size() / 10);
}

TEST(ColonizationView, ReplayShowsMoreSegmentsStepByStep) {
    const Skeleton skeleton = grow(load_template("elm"));
    const int last = last_iteration(skeleton);
    ASSERT_GT(last, 1);
    std::size_t before = 0;
    for (int step = 0; step <= last; ++step) {
        const std::vector<glm::vec3> lines = replay_lines(skeleton, step);
        EXPECT_GE(lines.size(), before) << "step " << step;
        before = lines.size();
    }
    EXPECT_EQ(before, 2 * skeleton.segments.size());  // the last step shows the whole tree
    // Half way, part of the tree. (Step 0 may show nothing: curve reduction merges the
    // straight trunk into the segment that ends at the first fork, made at a later step.)
    EXPECT_GT(replay_lines(skeleton, last / 2).size(), 0u);
    EXPECT_LT(replay_lines(skeleton, last / 2).size(), before);
    // Every segment shown hangs from one shown before it (or is a root): a tree, not debris.
    for (const Segment& s : skeleton.segments) {
        if (s.parent < 0) continue;
        EXPECT_LE(skeleton.segments[static_cast<std::size_t>(s.parent)].iteration, s.iteration);
    }
}

TEST(ColonizationView, LSystemSkeletonsHaveOneStep) {
    const Skeleton skeleton = grow(load_template("default"));
    EXPECT_EQ(last_iteration(skeleton), 0);
    EXPECT_EQ(replay_lines(skeleton, 0).size(), 2 * skeleton.segments.size());
}

}  // namespace
}  // namespace sylva::studio
