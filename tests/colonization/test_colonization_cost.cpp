// What space colonization costs: the work a run counts (the same on every run, reported as
// it rises, and a limit on it that stops the run) and the estimate made before one.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "colonization/attraction_points.h"
#include "colonization/colonization_cost.h"
#include "colonization/envelope.h"
#include "colonization/space_colonization.h"

namespace sylva {
namespace {

// An elm's crown: a wide ellipsoid lifted on a trunk.
Envelope crown() {
    Envelope e;
    e.shape = EnvelopeShape::Ellipsoid;
    e.size = {9.0f, 5.5f, 9.0f};
    e.base = {0.0f, 4.0f, 0.0f};
    return e;
}

ColonizationSettings settings(float kill_distance) {
    ColonizationSettings s;
    s.influence_radius = 2.2f;
    s.kill_distance = kill_distance;
    s.step_size = 0.4f;
    s.trunk_height = 3.0f;
    s.max_iterations = 200;
    return s;
}

std::vector<glm::vec3> points(int count) {
    return attraction_points(crown(), count, PointDistribution::Uniform, 3);
}

TEST(ColonizationCost, WorkIsCountedAlikeOnEveryRunAndReportedAsItRises) {
    const std::vector<glm::vec3> p = points(3000);
    ColonizationSettings s = settings(0.7f);
    std::vector<ColonizationWork> reports;
    s.work_done = [&](const ColonizationWork& w) { reports.push_back(w); };
    const ColonizationGraph a = colonize(p, glm::vec3(0.0f), s);
    ASSERT_FALSE(reports.empty());
    for (std::size_t k = 1; k < reports.size(); ++k) {
        EXPECT_GE(reports[k].visits, reports[k - 1].visits);
        EXPECT_GE(reports[k].scans, reports[k - 1].scans);
        EXPECT_GE(reports[k].nodes, reports[k - 1].nodes);
    }
    EXPECT_EQ(reports.back().visits, a.work.visits);
    EXPECT_EQ(a.work.nodes, a.nodes.size());
    EXPECT_EQ(a.work.iterations, a.iterations);
    EXPECT_GT(a.work.visits, 0u);
    const ColonizationGraph b = colonize(p, glm::vec3(0.0f), settings(0.7f));
    EXPECT_EQ(a.work.visits, b.work.visits);
    EXPECT_EQ(a.work.scans, b.work.scans);
}

// A kill distance far below the step leaves every point alive: each new node looks at the
// points around it, and the crown fills with nodes. A limit on the counted work stops such a
// run soon after it is passed, even within one pass.
TEST(ColonizationCost, ALimitOnTheWorkStopsTheRunSoonAfterItIsPassed) {
    const std::vector<glm::vec3> p = points(5000);
    ColonizationSettings s = settings(0.01f);
    const std::uint64_t limit = 2'000'000;
    std::uint64_t stopped_at = 0;
    s.work_done = [&](const ColonizationWork& w) {
        if (w.visits > limit) {
            stopped_at = w.visits;
            throw std::runtime_error("over the limit");
        }
    };
    EXPECT_THROW(colonize(p, glm::vec3(0.0f), s), std::runtime_error);
    EXPECT_GT(stopped_at, limit);
    // At most a report's interval (2^22 visits) and one node's look at every point past it.
    EXPECT_LT(stopped_at, limit + (std::uint64_t{1} << 22) + p.size());
    const ColonizationGraph whole = colonize(p, glm::vec3(0.0f), settings(0.01f));
    EXPECT_GT(whole.work.visits, 2 * limit);
}

// The estimate follows points x nodes: close to the count where the points stay alive (the
// costly case), above it where they die early, and far apart for a few thousand points and
// a million.
TEST(ColonizationCost, TheEstimateFollowsPointsTimesNodes) {
    const Box box = bounds(crown());
    for (const float kill : {0.01f, 0.7f}) {
        const std::vector<glm::vec3> p = points(5000);
        const ColonizationGraph g = colonize(p, glm::vec3(0.0f), settings(kill));
        const ColonizationCost estimate =
            estimate_colonization_cost(box, p.size(), 1, settings(kill));
        const ColonizationCost counted = colonization_cost(g.work, p.size(), box, settings(kill));
        const double visits = static_cast<double>(g.work.visits);
        const double nodes = static_cast<double>(g.work.nodes);
        EXPECT_GT(estimate.visits, 0.5 * visits) << "kill " << kill;
        EXPECT_GT(estimate.nodes, 0.5 * nodes) << "kill " << kill;
        if (kill < 0.1f) {
            EXPECT_LT(estimate.visits, 4.0 * visits);
            EXPECT_LT(estimate.nodes, 4.0 * nodes);
        }
        EXPECT_GT(estimate.seconds, 0.5 * counted.seconds) << "kill " << kill;
    }
    const ColonizationCost million =
        estimate_colonization_cost(box, 1'000'000, 1, settings(0.001f));
    EXPECT_GT(million.seconds, 10.0);
    EXPECT_LT(estimate_colonization_cost(box, 1400, 1, settings(0.7f)).seconds, 0.1);
}

}  // namespace
}  // namespace sylva
