#include "colonization/space_colonization.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "colonization/cell_grid.h"

namespace sylva {
namespace {

float distance2(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = a - b;
    return glm::dot(d, d);
}

Box padded_bounds(std::span<const glm::vec3> points, std::span<const glm::vec3> roots, float pad) {
    Box box{roots[0], roots[0]};
    for (const glm::vec3& p : roots) {
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
    }
    for (const glm::vec3& p : points) {
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
    }
    return {box.min - glm::vec3(pad), box.max + glm::vec3(pad)};
}

// The state of one run. Each attraction point remembers its nearest active node within
// d_i. With the grid, that memory is updated only where a node appears or stops
// attracting, so an iteration costs what changed, not points x nodes.
class Colonizer {
  public:
    Colonizer(std::span<const glm::vec3> points, std::span<const glm::vec3> roots,
              const ColonizationSettings& settings)
        : s_(settings),
          points_(points.begin(), points.end()),
          nearest_(points.size(), -1),
          nearest_d2_(points.size(), std::numeric_limits<float>::infinity()),
          alive_(points.size(), 1),
          alive_count_(points.size()),
          di2_(settings.influence_radius * settings.influence_radius),
          dk2_(settings.kill_distance * settings.kill_distance),
          // Points are many and dense: half-d_i cells visit less of them per query.
          point_grid_(padded_bounds(points, roots, settings.influence_radius),
                      0.5f * settings.influence_radius),
          node_grid_(padded_bounds(points, roots, settings.influence_radius),
                     settings.influence_radius) {
        assert(settings.kill_distance > 0.0f && settings.step_size > 0.0f);
        for (size_t i = 0; i < points_.size(); ++i)
            point_grid_.insert(static_cast<int>(i), points_[i]);
        for (const glm::vec3& root : roots) add_node(root, -1, 0);
        roots_ = static_cast<int>(roots.size());
    }

    ColonizationGraph run() {
        ColonizationGraph graph;
        grow_trunk();
        if (s_.search == NearestSearch::BruteForce) refresh_brute_force();
        graph.stop = ColonizationStop::MaxIterations;
        float reported = 0.0f;
        for (; graph.iterations < s_.max_iterations; ++graph.iterations) {
            throw_if_cancelled(s_.cancel);
            if (s_.progress) {
                const float points = points_.empty()
                                         ? 1.0f
                                         : 1.0f - static_cast<float>(alive_count_) /
                                                      static_cast<float>(points_.size());
                const float iterations = static_cast<float>(graph.iterations) /
                                         static_cast<float>(std::max(s_.max_iterations, 1));
                reported = std::max({reported, points, iterations});
                s_.progress(std::min(reported, 1.0f));
            }
            if (alive_count_ == 0) {
                graph.stop = ColonizationStop::NoPointsLeft;
                break;
            }
            iteration_ = graph.iterations + 1;
            const bool grew = iterate();
            report_work();
            if (!grew) {
                graph.stop = ColonizationStop::NothingGrew;
                break;
            }
        }
        if (s_.progress) s_.progress(1.0f);
        graph.oscillations = oscillations_;
        graph.idle_attracted = idle_attracted_;
        graph.moved_growth = moved_growth_;
        graph.work = work(graph.iterations);
        graph.nodes = std::move(nodes_);
        for (size_t i = 0; i < points_.size(); ++i)
            if (alive_[i]) graph.remaining.push_back(points_[i]);
        return graph;
    }

  private:
    ColonizationWork work(int iterations) const {
        return {iterations, nodes_.size(), scans_, visits_};
    }

    void report_work() {
        reported_visits_ = visits_;
        if (s_.work_done) s_.work_done(work(iteration_));
    }

    bool active(int node) const {
        return s_.max_no_grow <= 0 || nodes_[static_cast<size_t>(node)].no_grow < s_.max_no_grow;
    }

    // Weighted growth: 2D at depth 0 down to D at the deepest branches.
    float step(int depth) const {
        if (!s_.weighted_growth) return s_.step_size;
        const float deepest = static_cast<float>(s_.max_depth > 0 ? s_.max_depth : 8);
        return s_.step_size * (2.0f - std::min(1.0f, static_cast<float>(depth) / deepest));
    }

    void add_node(const glm::vec3& position, int parent, int depth) {
        const int index = static_cast<int>(nodes_.size());
        nodes_.push_back({position, parent, depth, 0, 0, iteration_});
        if (parent >= 0) {
            ColonizationNode& p = nodes_[static_cast<size_t>(parent)];
            ++p.successors;
            p.no_grow = 0;
        }
        if (s_.search == NearestSearch::BruteForce) return;  // refreshed once per iteration
        node_grid_.insert(index, position);
        point_grid_.filter_near(position, s_.influence_radius, [&](int i) {
            ++visits_;
            const auto k = static_cast<size_t>(i);
            const float d2 = distance2(points_[k], position);
            if (d2 <= dk2_) {
                alive_[k] = 0;
                --alive_count_;
                return false;
            }
            // Strictly closer only: among equal distances the older node wins, as in a
            // scan in index order.
            if (d2 <= di2_ && d2 < nearest_d2_[k]) {
                nearest_[k] = index;
                nearest_d2_[k] = d2;
            }
            return true;
        });
        if (visits_ - reported_visits_ >= kVisitsBetweenReports) report_work();
    }

    bool point_within(const glm::vec3& p, float radius) {
        bool found = false;
        point_grid_.for_each_near(p, radius, [&](int i) {
            ++visits_;
            const auto k = static_cast<size_t>(i);
            found = found || (alive_[k] && distance2(points_[k], p) <= radius * radius);
        });
        return found;
    }

    // Straight up from each root until the crown's points are in reach (or an obstacle).
    void grow_trunk() {
        for (int root = 0; root < roots_; ++root) {
            float top = nodes_[static_cast<size_t>(root)].position.y;
            for (const glm::vec3& p : points_) top = std::max(top, p.y);
            scans_ += points_.size();
            const float root_y = nodes_[static_cast<size_t>(root)].position.y;
            int tip = root;
            for (;;) {
                throw_if_cancelled(s_.cancel);
                const glm::vec3 at = nodes_[static_cast<size_t>(tip)].position;
                const bool tall_enough = at.y - root_y >= s_.trunk_height - 1e-6f;
                if (tall_enough && (point_within(at, s_.influence_radius) || at.y >= top)) break;
                const glm::vec3 next = at + glm::vec3(0.0f, step(0), 0.0f);
                if (s_.blocked && s_.blocked(next)) break;
                add_node(next, tip, 0);
                tip = static_cast<int>(nodes_.size()) - 1;
            }
        }
    }

    // Liebemann 2017, 5.3: a new node that lands back on the tree (within D/2 of a node) is
    // growth going back and forth between equally distant points; refuse it.
    bool crowded(const glm::vec3& p) {
        const float limit2 = 0.25f * s_.step_size * s_.step_size;
        if (s_.search == NearestSearch::BruteForce) {
            scans_ += nodes_.size();
            for (const ColonizationNode& n : nodes_)
                if (distance2(n.position, p) < limit2) return true;
            return false;
        }
        bool found = false;
        node_grid_.for_each_near(p, 0.5f * s_.step_size, [&](int j) {
            ++visits_;
            found = found || distance2(nodes_[static_cast<size_t>(j)].position, p) < limit2;
        });
        return found;
    }

    // One iteration of Liebemann 2017, 3.3. Returns whether any node grew.
    bool iterate() {
        // Step 1: S(v) as the sum of unit directions to v's points (eq. 3.3).
        const size_t existing = nodes_.size();
        scans_ += points_.size() + 2 * existing;  // steps 1 and 2, and max_NG's pass
        sum_.assign(existing, glm::vec3(0.0f));
        count_.assign(existing, 0);
        pulled_by_moved_.assign(existing, 0);
        for (size_t i = 0; i < points_.size(); ++i) {
            if (!alive_[i] || nearest_[i] < 0) continue;
            const auto v = static_cast<size_t>(nearest_[i]);
            sum_[v] += glm::normalize(points_[i] - nodes_[v].position);
            ++count_[v];
            pulled_by_moved_[v] |= moved_[i];
        }
        // Step 2: every influenced node grows one successor at step D (eq. 3.1, 3.2).
        grew_.assign(existing, 0);
        bool any = false;
        for (size_t v = 0; v < existing; ++v) {
            if (count_[v] == 0) continue;
            const ColonizationNode node = nodes_[v];
            if (s_.max_degree > 0 && node.successors >= s_.max_degree) continue;
            // Eq. 3.5: the first successor continues the branch, a further one starts one.
            const int depth = node.successors == 0 ? node.depth : node.depth + 1;
            if (s_.max_depth > 0 && depth > s_.max_depth) continue;
            const float pull = glm::length(sum_[v]);
            if (pull < 1e-4f * static_cast<float>(count_[v])) {
                ++oscillations_;  // the points pull in opposite directions
                continue;
            }
            glm::vec3 direction = sum_[v] / pull + s_.tropism;
            if (s_.tropism_field) direction += s_.tropism_field(node.position);
            const float length = glm::length(direction);
            if (length < 1e-6f) continue;
            const glm::vec3 p = node.position + direction * (step(node.depth) / length);
            if (s_.blocked && s_.blocked(p)) continue;
            if (crowded(p)) {
                ++oscillations_;
                continue;
            }
            add_node(p, static_cast<int>(v), depth);
            grew_[v] = 1;
            moved_growth_ += pulled_by_moved_[v];
            any = true;
        }
        // max_NG: count the passes without growth; a node reaching it stops attracting,
        // and its points look for the next nearest node. While an attracted node that did
        // not grow still waits for that, the growth is not over: its points may yet move to
        // a node that can grow (without this, a growth whose last pass grew nothing, as the
        // hedge's, never let max_no_grow act).
        bool waiting = false;
        for (size_t v = 0; v < existing; ++v) {
            if (grew_[v]) continue;
            idle_attracted_ += count_[v] > 0;
            waiting = waiting || (s_.max_no_grow > 0 && count_[v] > 0);
            const int before = nodes_[v].no_grow++;
            if (s_.max_no_grow > 0 && before + 1 == s_.max_no_grow &&
                s_.search == NearestSearch::Grid)
                release_points_of(static_cast<int>(v));
        }
        // Step 3 (kill) happened as nodes were added; brute force does it all here.
        if (s_.search == NearestSearch::BruteForce) refresh_brute_force();
        return any || waiting;
    }

    void release_points_of(int node) {
        const glm::vec3 at = nodes_[static_cast<size_t>(node)].position;
        point_grid_.for_each_near(at, s_.influence_radius, [&](int i) {
            ++scans_;  // most are another node's points: two flags read, no distance
            const auto k = static_cast<size_t>(i);
            if (!alive_[k] || nearest_[k] != node) return;
            nearest_[k] = -1;
            nearest_d2_[k] = std::numeric_limits<float>::infinity();
            node_grid_.for_each_near(points_[k], s_.influence_radius, [&](int j) {
                ++scans_;  // nodes in cache, most of them stalled: cheap
                if (!active(j)) return;
                const float d2 = distance2(points_[k], nodes_[static_cast<size_t>(j)].position);
                if (d2 <= di2_ &&
                    (d2 < nearest_d2_[k] || (d2 == nearest_d2_[k] && j < nearest_[k]))) {
                    nearest_[k] = j;
                    nearest_d2_[k] = d2;
                }
            });
            moved_[k] = nearest_[k] >= 0;
        });
    }

    // The reference: every live point against every node.
    void refresh_brute_force() {
        scans_ += points_.size() * nodes_.size();
        for (size_t k = 0; k < points_.size(); ++k) {
            if (!alive_[k]) continue;
            nearest_[k] = -1;
            nearest_d2_[k] = std::numeric_limits<float>::infinity();
            for (size_t j = 0; j < nodes_.size(); ++j) {
                const float d2 = distance2(points_[k], nodes_[j].position);
                if (d2 <= dk2_) {
                    alive_[k] = 0;
                    --alive_count_;
                    break;
                }
                if (d2 <= di2_ && d2 < nearest_d2_[k] && active(static_cast<int>(j))) {
                    nearest_[k] = static_cast<int>(j);
                    nearest_d2_[k] = d2;
                }
            }
        }
    }

    const ColonizationSettings& s_;
    std::vector<ColonizationNode> nodes_;
    std::vector<glm::vec3> points_;
    std::vector<int> nearest_;
    std::vector<float> nearest_d2_;
    std::vector<char> alive_;
    size_t alive_count_;
    float di2_, dk2_;
    CellGrid point_grid_, node_grid_;
    std::vector<glm::vec3> sum_;
    std::vector<int> count_;
    std::vector<char> grew_;
    int oscillations_ = 0;
    int idle_attracted_ = 0;
    int moved_growth_ = 0;
    // Per point: handed on by a release (max_no_grow).
    std::vector<char> moved_ = std::vector<char>(points_.size(), 0);
    std::vector<char> pulled_by_moved_;  // per node, this pass: a moved point attracts it
    int iteration_ = 0;                  // 0 while the trunk grows
    std::uint64_t scans_ = 0, visits_ = 0, reported_visits_ = 0;
    // A few tens of milliseconds of queries: a limit on the work holds within that.
    static constexpr std::uint64_t kVisitsBetweenReports = std::uint64_t{1} << 22;
    int roots_ = 0;  // nodes_[0, roots_) are the roots
};

}  // namespace

ColonizationGraph colonize(std::span<const glm::vec3> points, const glm::vec3& root,
                           const ColonizationSettings& settings) {
    return colonize(points, std::span<const glm::vec3>(&root, 1), settings);
}

ColonizationGraph colonize(std::span<const glm::vec3> points, std::span<const glm::vec3> roots,
                           const ColonizationSettings& settings) {
    assert(!roots.empty());
    return Colonizer(points, roots, settings).run();
}

}  // namespace sylva
