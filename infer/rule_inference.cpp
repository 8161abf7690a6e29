#include "infer/rule_inference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <optional>
#include <regex>
#include <sstream>

#include "core/errors.h"
#include "core/pipe_model.h"
#include "infer/branch_graph.h"
#include "infer/skeleton_figures.h"
#include "tree/growth.h"
#include "tree/template_file.h"
#include "turtle/lsystem_params.h"

namespace sylva {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr char kLetters[] = "ABCDEGHIJKMN";  // module names: capitals the turtle ignores
constexpr int kMaxModules = 12;
// A trunk of at most this many nodes is written out in the axiom, node by node, with its
// first-order branches as calls: it is where the example differs most from any rule and
// where an error shows most.
constexpr int kLiteralTrunkNodes = 6;

// How a turn leaves the turtle's frame, that is which frame the next angles are measured
// in. Vertical: rolled so that the left vector is horizontal (`$` after every turn, ABOP
// 1.5), so a branch angle means the same on every branch whatever the turtle rolled
// before. Minimal: turned by the smallest rotation onto the new heading
// (`/(a)&(b)\(a)`, parallel transport), so the rolls a grammar makes without `$` add up
// as they do in its turtle. Which one regrows an example better is tried.
enum class Convention { Vertical, Minimal };

// ---- the turtle's frame, as turtle/turtle.cpp moves it (ABOP's H, L, U) ----------------
struct Frame {
    glm::dvec3 h{0.0, 1.0, 0.0};
    glm::dvec3 l{-1.0, 0.0, 0.0};
    glm::dvec3 u{0.0, 0.0, 1.0};
};

void orthonormalize(Frame& f) {
    f.h = glm::normalize(f.h);
    f.l = glm::normalize(f.l - f.h * glm::dot(f.l, f.h));
    f.u = glm::cross(f.h, f.l);
}
void rotate_pair(glm::dvec3& a, glm::dvec3& b, double degrees) {
    const double c = std::cos(degrees * kDegree), s = std::sin(degrees * kDegree);
    const glm::dvec3 a2 = a * c + b * s;
    b = b * c - a * s;
    a = a2;
}
void roll(Frame& f, double degrees) {
    rotate_pair(f.l, f.u, degrees);
    orthonormalize(f);
}
void pitch(Frame& f, double degrees) {
    rotate_pair(f.h, f.u, -degrees);
    orthonormalize(f);
}
void roll_to_vertical(Frame& f) {
    const glm::dvec3 l = glm::cross(glm::dvec3(0.0, 1.0, 0.0), f.h);
    const double n = glm::length(l);
    if (n < 1e-12) return;
    f.l = l / n;
    f.u = glm::cross(f.h, f.l);
}
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& k, double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
}
void bend(Frame& f, double elasticity) {
    if (elasticity == 0.0) return;
    glm::dvec3 axis = glm::cross(f.h, glm::dvec3(0.0, -1.0, 0.0));
    const double strength = glm::length(axis);
    if (strength < 1e-12) return;
    axis /= strength;
    f.h = rotate(f.h, axis, elasticity * strength);
    f.l = rotate(f.l, axis, elasticity * strength);
    orthonormalize(f);
}

// `/(az)&(pitch)` turns a frame's heading onto a direction.
struct Turn {
    double az = 0.0;
    double pitch = 0.0;
};
Turn solve(const Frame& f, const glm::dvec3& d) {
    const double hh = glm::dot(d, f.h), ll = glm::dot(d, f.l), uu = glm::dot(d, f.u);
    const double r = std::sqrt(ll * ll + uu * uu);
    Turn t;
    t.pitch = std::atan2(r, hh) / kDegree;
    if (r > 1e-9) t.az = -std::atan2(ll, -uu) / kDegree;
    return t;
}
Frame turned(Frame f, const Turn& t, Convention convention) {
    roll(f, -t.az);
    pitch(f, t.pitch);
    if (convention == Convention::Vertical)
        roll_to_vertical(f);
    else
        roll(f, t.az);
    return f;
}

// ---- statistics -------------------------------------------------------------------------
struct Circular {
    double s = 0.0, c = 0.0;
    int n = 0;
    void add(double degrees, double weight = 1.0) {
        s += weight * std::sin(degrees * kDegree);
        c += weight * std::cos(degrees * kDegree);
        ++n;
    }
    double mean() const { return n ? std::atan2(s, c) / kDegree : 0.0; }
    double strength() const { return n ? std::hypot(s, c) / n : 0.0; }
};
struct Mean {
    double sum = 0.0, squares = 0.0;
    int n = 0;
    void add(double v) {
        sum += v;
        squares += v * v;
        ++n;
    }
    double mean(double fallback = 0.0) const { return n ? sum / n : fallback; }
    // The squared standard error of the mean (0 for fewer than two values).
    double error2() const {
        return n > 1 ? std::max(0.0, (squares - sum * sum / n) / (n - 1)) / n : 0.0;
    }
};

// Whether two means differ by no more than three standard errors of their difference:
// then a rule states one value for both (slots of a whorl at one angle), where the
// measured difference is noise that would turn every branch of one slot.
bool same_within_noise(const Mean& a, const Mean& b) {
    const double error = std::sqrt(a.error2() + b.error2());
    return std::abs(a.mean() - b.mean()) <= 3.0 * error;
}
struct Ratio {  // geometric mean of positive ratios
    Mean log;
    void add(double num, double den) {
        if (num > 0.0 && den > 0.0) log.add(std::log(num / den));
    }
    double mean() const { return std::exp(log.mean(0.0)); }
};
double wrap(double degrees) {
    degrees = std::fmod(degrees, 360.0);
    if (degrees > 180.0) degrees -= 360.0;
    if (degrees <= -180.0) degrees += 360.0;
    return degrees;
}

// A turn that recurs (the bend between two segments of an axis), as the mean of turn
// vectors (pitch in the direction az): turns in scattered directions cancel out, and a
// mean no larger than its noise is none.
struct TurnMean {
    double x = 0.0, y = 0.0, xx = 0.0, yy = 0.0;
    int n = 0;
    void add(const Turn& t, double reference = 0.0) {
        const double a = (t.az - reference) * kDegree;
        const double px = t.pitch * std::cos(a), py = t.pitch * std::sin(a);
        x += px, y += py, xx += px * px, yy += py * py;
        ++n;
    }
    double magnitude() const { return n ? std::hypot(x, y) / n : 0.0; }
    // The mean's size over its standard error: above 3 the turn is more than noise.
    double significance() const {
        if (n < 2) return n == 1 && magnitude() > 0.05 ? 1e9 : 0.0;
        const double mx = x / n, my = y / n;
        const double var = std::max((xx + yy) / n - mx * mx - my * my, 0.0);
        const double error = std::sqrt(var / n);
        return error < 1e-9 ? 1e9 : magnitude() / error;
    }
    Turn mean() const {
        if (!n) return {};
        return {std::atan2(y, x) / kDegree, magnitude()};
    }
};

// ---- what is measured per segment --------------------------------------------------------
struct Measured {
    std::vector<double> length, width;  // width: diameter at the segment's start
    std::vector<Turn> turn;             // from the parent's end frame (a root: the start frame)
    std::vector<int> budget;            // the height budget m the module has at the segment
    std::vector<int> node;              // index on its axis
};

Measured measure(const Skeleton& skeleton, const BranchGraph& g, double elasticity,
                 Convention convention) {
    const std::size_t count = skeleton.segments.size();
    Measured m;
    m.length.resize(count);
    m.width.resize(count);
    m.turn.resize(count);
    m.budget.resize(count);
    m.node.resize(count);
    std::vector<Frame> end(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Segment& s = skeleton.segments[i];
        const glm::dvec3 d = glm::normalize(glm::dvec3(s.b) - glm::dvec3(s.a));
        const Frame from = s.parent < 0 ? Frame{} : end[static_cast<std::size_t>(s.parent)];
        m.turn[i] = solve(from, d);
        Frame f = turned(from, m.turn[i], convention);
        // The turned frame's heading is d up to rounding; take d itself so errors do not add up.
        f.h = d;
        orthonormalize(f);
        bend(f, elasticity);
        end[i] = f;
        m.length[i] = glm::length(glm::dvec3(s.b) - glm::dvec3(s.a));
        m.width[i] = 2.0 * s.ra;
    }
    for (const Axis& axis : g.axes) {
        const int base = g.height[static_cast<std::size_t>(axis.segments.front())];
        for (std::size_t j = 0; j < axis.segments.size(); ++j) {
            m.budget[static_cast<std::size_t>(axis.segments[j])] = base - static_cast<int>(j);
            m.node[static_cast<std::size_t>(axis.segments[j])] = static_cast<int>(j);
        }
    }
    return m;
}

std::vector<int> laterals_of(const BranchGraph& g, int s) {
    std::vector<int> out;
    for (int c : g.children[static_cast<std::size_t>(s)])
        if (c != g.continuation[static_cast<std::size_t>(s)]) out.push_back(c);
    return out;
}

// ---- one module: the fitted pattern of a set of axes ----------------------------------------
// A whole number a lateral axis gets from the budget b its parent node leaves it (its
// segments, its own budget): b, min(b, cap) or min(b, round(share * b)).
struct FromBudget {
    enum Kind { Budget, Cap, Share } kind = Budget;
    int cap = 0;
    double share = 1.0;
    int of(int b) const {
        if (kind == Cap) return std::min(b, cap);
        if (kind == Share) return std::min(b, static_cast<int>(std::floor(share * b + 0.5)));
        return b;
    }
    std::string text(const std::string& b) const;
};

// The model that errs least over the samples (value, budget); the simplest on a tie.
FromBudget fit_from_budget(const std::vector<std::pair<int, int>>& samples, long* error_out) {
    auto error = [&](const FromBudget& f) {
        long e = 0;
        for (auto [v, b] : samples) e += std::abs(v - f.of(b));
        return e;
    };
    FromBudget best;
    long best_error = error(best);
    std::vector<int> caps;
    for (auto [v, b] : samples) caps.push_back(v);
    std::sort(caps.begin(), caps.end());
    caps.erase(std::unique(caps.begin(), caps.end()), caps.end());
    for (int c : caps) {
        const FromBudget f{FromBudget::Cap, c, 1.0};
        if (const long e = error(f); e < best_error) best = f, best_error = e;
    }
    double sv = 0.0, sb = 0.0;
    for (auto [v, b] : samples) sv += v, sb += b;
    if (sb > 0.0) {
        const FromBudget f{FromBudget::Share, 0, std::min(1.0, sv / sb)};
        if (const long e = error(f); e < best_error) best = f, best_error = e;
    }
    *error_out = best_error;
    return best;
}

struct Slot {
    double offset = 0.0;  // azimuth after the node's first lateral, degrees
    double pitch = 0.0;   // branch angle, degrees
    double length = 1.0;  // first segment's length over the parent segment's
    double width = 1.0;   // and its width over the parent's
    double chance = 1.0;  // probability that a node has this lateral (k > index)
    // The lateral's segments and its own height budget, from the budget b its node leaves.
    FromBudget count, height;
    int drop = 0;  // b is the node's budget less 1 + drop
    // The phase of the lateral axes it starts: its azimuth plus this when the child module's
    // phase is relative, else this.
    double child_phase = 0.0;
};

// The laterals of one kind of node: how many (weighted alternatives) and each one's slot.
struct NodePattern {
    std::vector<std::pair<int, double>> ks;  // lateral counts with their frequencies
    std::vector<Slot> slots;
    int nodes = 0;  // nodes the pattern was fitted on
};

struct Module {
    std::vector<int> axes;                // the example's axes it stands for
    int first_order = 0, last_order = 0;  // orders it covers (recursive when more)
    // Laterals along the axis, and at its last node when that differs (a whorl at the tip,
    // a fork ending the axis): then the last node has only those.
    NodePattern interior, tip;
    bool has_tip = false;
    double tip_offset = 0.0;  // the tip's first lateral's azimuth after the phase
    double advance = 0.0;     // divergence: phase change from one node to the next, degrees
    // The turn before the next segment of the axis; its azimuth after the node's phase when
    // relative (the bend turns with the branches, a grammar's roll between nodes).
    Turn bend;
    bool bend_relative = false;
    double length_ratio = 1.0, width_ratio = 1.0;
    bool length_known = false;  // some axis had two segments
    int budget_drop = 0;        // a lateral's height budget: the node's minus 1 minus this
    // How this module's axes are as laterals: their first phase (absolute, or their spawn
    // azimuth plus this).
    bool phase_relative = false;
    double phase = 0.0;
    bool phase_known = false;
    // Nodes without branches at the base of every axis (a bare stretch), drawn by a head rule.
    int bare = 0;
    // When positive, a segment is drawn only while its length exceeds this: axes that end
    // where their segments grow too short rather than where a count runs out.
    double stop = 0.0;
    // After it, laterals every `period` nodes (internodes of several segments, a whorl every
    // few); a rewrite draws the period's segments, branching at the first.
    int period = 1;
    // How many phase steps (divergences) lie before node j.
    double phase_steps(std::size_t j) const {
        const int n = static_cast<int>(j);
        return n < bare ? n : bare + (n - bare) / period;
    }
    double head_ratio = 1.0;  // the first branched segment's length over the axis's first
    // Per axis: its segment length at the end of the bare stretch, from the fitted line.
    std::vector<std::optional<double>> start_length;
    std::vector<std::optional<double>> axis_phase;  // per axis: the phase of its node 0
};

struct NodeSample {
    std::vector<int> laterals;
    int segment;
};

void fit_pattern(NodePattern& pattern, const std::vector<NodeSample>& nodes, const Measured& m) {
    std::map<int, int> k_count;
    std::vector<Circular> offsets;
    std::vector<Mean> pitches;
    std::vector<Ratio> lengths, widths;
    for (const NodeSample& node : nodes) {
        const std::vector<int>& lat = node.laterals;
        const std::size_t si = static_cast<std::size_t>(node.segment);
        ++k_count[static_cast<int>(lat.size())];
        if (lat.size() > offsets.size()) {
            offsets.resize(lat.size());
            pitches.resize(lat.size());
            lengths.resize(lat.size());
            widths.resize(lat.size());
        }
        const double first = lat.empty() ? 0.0 : m.turn[static_cast<std::size_t>(lat[0])].az;
        for (std::size_t i = 0; i < lat.size(); ++i) {
            const std::size_t c = static_cast<std::size_t>(lat[i]);
            offsets[i].add(m.turn[c].az - first);
            pitches[i].add(m.turn[c].pitch);
            lengths[i].add(m.length[c], m.length[si]);
            widths[i].add(m.width[c], m.width[si]);
        }
    }
    pattern.nodes = static_cast<int>(nodes.size());
    // Lateral counts: those seen at 5 % of the nodes or more, with their frequencies.
    for (const auto& [k, n] : k_count)
        if (n * 20 >= pattern.nodes) pattern.ks.emplace_back(k, static_cast<double>(n));
    if (pattern.ks.empty() && !k_count.empty())
        pattern.ks.emplace_back(k_count.rbegin()->first, 1.0);
    double total = 0.0;
    for (auto& [k, w] : pattern.ks) total += w;
    for (auto& [k, w] : pattern.ks) w /= total;
    int kmax = 0;
    for (auto& [k, w] : pattern.ks) kmax = std::max(kmax, k);
    pattern.slots.resize(static_cast<std::size_t>(kmax));
    for (std::size_t i = 0; i < pattern.slots.size() && i < offsets.size(); ++i) {
        Slot& slot = pattern.slots[i];
        slot.offset = i == 0 ? 0.0 : wrap(offsets[i].mean());
        slot.pitch = pitches[i].mean();
        slot.length = lengths[i].mean();
        if (i > 0 && same_within_noise(pitches[i], pitches[0])) slot.pitch = pattern.slots[0].pitch;
        if (i > 0 && same_within_noise(lengths[i].log, lengths[0].log))
            slot.length = pattern.slots[0].length;
        slot.width = widths[i].mean();
        double more = 0.0;
        for (auto& [k, w] : pattern.ks)
            if (k > static_cast<int>(i)) more += w;
        slot.chance = more;
    }
}

// The divergence that makes `y - dv * x` (minus `spawn` when relative) agree best over the
// samples, found on a grid of a quarter degree: for phases seen once per axis at nodes
// that differ from axis to axis (a fork at the tip of axes of different lengths).
struct PhaseSample {
    int node;
    double az;
    std::optional<double> spawn;
};
double regress_divergence(const std::vector<PhaseSample>& samples) {
    auto agreement = [&](double dv) {
        Circular absolute, relative;
        for (const PhaseSample& s : samples) {
            absolute.add(s.az - dv * s.node);
            if (s.spawn) relative.add(s.az - dv * s.node - *s.spawn);
        }
        return std::max(absolute.strength(), relative.strength());
    };
    double best = 0.0, best_score = agreement(0.0) + 0.02;  // no divergence unless clearly better
    for (int k = -720; k < 720; ++k) {
        const double dv = 0.25 * k;
        const double score = agreement(dv);
        if (score > best_score) best_score = score, best = dv;
    }
    const double centre = best;
    for (int k = -25; k <= 25; ++k) {
        const double dv = centre + 0.01 * k;
        const double score = agreement(dv);
        if (score > best_score) best_score = score, best = dv;
    }
    return wrap(best);
}

// `allow_tip`: whether an axis whose only laterals sit at its last node may take them as
// a tip pattern (else they are interior laterals after a bare stretch).
Module fit_module(const std::vector<int>& axes, const BranchGraph& g, const Measured& m,
                  bool allow_tip) {
    Module mod;
    mod.axes = axes;
    auto seg = [](int s) { return static_cast<std::size_t>(s); };
    // A lateral's budget: the node's, less what the example shows it loses.
    Mean drop;
    for (int a : axes)
        for (int s : g.axes[seg(a)].segments)
            for (int c : laterals_of(g, s)) drop.add(m.budget[seg(s)] - 1 - g.height[seg(c)]);
    mod.budget_drop = std::max(0, static_cast<int>(std::lround(drop.mean(0.0))));
    auto can_branch = [&](int s) { return m.budget[seg(s)] - 1 - mod.budget_drop > 0; };

    // The tip: an axis's last node that has laterals, when the axes have no laterals before it.
    int tip_nodes = 0, interior_laterals = 0;
    for (int a : axes) {
        const Axis& axis = g.axes[seg(a)];
        if (!laterals_of(g, axis.segments.back()).empty()) ++tip_nodes;
        for (std::size_t j = 0; j + 1 < axis.segments.size(); ++j)
            interior_laterals += !laterals_of(g, axis.segments[j]).empty();
    }
    mod.has_tip = allow_tip && tip_nodes > 0 && interior_laterals == 0;

    // The bare stretch: leading nodes without laterals, where most branched axes agree.
    if (!mod.has_tip) {
        std::map<int, int> leading;
        int branched = 0;
        for (int a : axes) {
            const Axis& axis = g.axes[seg(a)];
            for (std::size_t j = 0; j < axis.segments.size(); ++j)
                if (!laterals_of(g, axis.segments[j]).empty()) {
                    ++leading[static_cast<int>(j)];
                    ++branched;
                    break;
                }
        }
        for (const auto& [count, n] : leading)
            if (count > 0 && n * 10 >= branched * 7) mod.bare = count;
        // The period: the gap between branched nodes most axes keep.
        std::map<int, int> gaps;
        int gap_count = 0;
        for (int a : axes) {
            const Axis& axis = g.axes[seg(a)];
            int last = -1;
            for (std::size_t j = static_cast<std::size_t>(mod.bare); j < axis.segments.size();
                 ++j) {
                if (laterals_of(g, axis.segments[j]).empty()) continue;
                if (last >= 0) ++gaps[static_cast<int>(j) - last], ++gap_count;
                last = static_cast<int>(j);
            }
        }
        for (const auto& [gap, n] : gaps)
            if (gap > 1 && n * 10 >= gap_count * 8) mod.period = gap;
    }
    // The length ratio by least squares over the log lengths along every axis after its
    // bare stretch (one slope, an intercept per axis), and each axis's length at the end of
    // its bare stretch from its line: every segment counts, where the ratios of neighbours
    // would rest on an axis's first and last segment alone, and a length measured with
    // noise would scale all that follows it.
    double sxx = 0.0, sxy = 0.0;
    std::vector<std::pair<double, double>> means(axes.size(), {0.0, 0.0});  // (j, log length)
    std::vector<int> counted(axes.size(), 0);
    for (std::size_t k = 0; k < axes.size(); ++k) {
        const Axis& axis = g.axes[seg(axes[k])];
        double sj = 0.0, sy = 0.0;
        int n = 0;
        for (std::size_t j = static_cast<std::size_t>(mod.bare); j < axis.segments.size(); ++j) {
            sj += static_cast<double>(j);
            sy += std::log(m.length[seg(axis.segments[j])]);
            ++n;
        }
        if (n == 0) continue;
        means[k] = {sj / n, sy / n};
        counted[k] = n;
        for (std::size_t j = static_cast<std::size_t>(mod.bare); j < axis.segments.size(); ++j) {
            const double dx = static_cast<double>(j) - means[k].first;
            sxx += dx * dx;
            sxy += dx * (std::log(m.length[seg(axis.segments[j])]) - means[k].second);
        }
    }
    const double log_ratio = sxx > 0.0 ? sxy / sxx : 0.0;
    mod.start_length.assign(axes.size(), std::nullopt);
    Ratio head_ratio;
    for (std::size_t k = 0; k < axes.size(); ++k) {
        if (counted[k] == 0) continue;
        const Axis& axis = g.axes[seg(axes[k])];
        const double at_bare = std::exp(means[k].second + log_ratio * (mod.bare - means[k].first));
        mod.start_length[k] = at_bare;
        if (mod.bare > 0) head_ratio.add(at_bare, m.length[seg(axis.segments[0])]);
    }
    mod.head_ratio = head_ratio.mean();

    // Nodes, bends and ratios.
    std::vector<NodeSample> interior, tips;
    Ratio length_ratio, width_ratio;
    Circular advance;
    for (int a : axes) {
        const Axis& axis = g.axes[seg(a)];
        const std::size_t n = axis.segments.size();
        double previous_first = 0.0;  // the last node's first lateral's azimuth, when it had one
        bool have_previous = false;
        for (std::size_t j = 0; j < n; ++j) {
            const int s = axis.segments[j];
            const int next = g.continuation[seg(s)];
            if (static_cast<int>(j) < mod.bare) continue;
            if (next >= 0) {
                length_ratio.add(m.length[seg(next)], m.length[seg(s)]);
                width_ratio.add(m.width[seg(next)], m.width[seg(s)]);
                mod.length_known = true;
            }
            std::vector<int> lat = laterals_of(g, s);
            if (mod.has_tip && j + 1 == n) {
                if (!lat.empty()) tips.push_back({lat, s});
                continue;
            }
            if ((static_cast<int>(j) - mod.bare) % mod.period != 0) continue;
            if (g.children[seg(s)].empty() || !can_branch(s)) {
                have_previous = false;
                continue;
            }
            if (!lat.empty()) {
                const double first = m.turn[seg(lat[0])].az;
                if (have_previous) advance.add(first - previous_first);
                previous_first = first;
            }
            have_previous = !lat.empty();
            interior.push_back({std::move(lat), s});
        }
    }
    fit_pattern(mod.interior, interior, m);
    fit_pattern(mod.tip, tips, m);
    mod.length_ratio = sxx > 0.0 ? std::exp(log_ratio) : length_ratio.mean();
    mod.width_ratio = width_ratio.mean();

    // Bends: absolute first, to find a divergence where no two branched nodes follow.
    // `reference` gives the azimuth a bend is measured from, none to leave the bend out.
    auto bends_of = [&](const std::function<std::optional<double>(int, std::size_t)>& reference) {
        TurnMean t;
        for (int a : axes) {
            const Axis& axis = g.axes[seg(a)];
            for (std::size_t j = static_cast<std::size_t>(mod.bare); j + 1 < axis.segments.size();
                 ++j)
                if (const std::optional<double> r = reference(a, j))
                    t.add(m.turn[seg(axis.segments[j + 1])], *r);
        }
        return t;
    };
    // The roll from one node to the next as the axes' bends show it, where they agree.
    const auto advance_from_bends = [&] {
        Circular steps;
        for (int a : axes) {
            const Axis& axis = g.axes[seg(a)];
            for (std::size_t j = 0; j + 2 < axis.segments.size(); ++j) {
                const Turn& t0 = m.turn[seg(axis.segments[j + 1])];
                const Turn& t1 = m.turn[seg(axis.segments[j + 2])];
                if (t0.pitch > 0.05 && t1.pitch > 0.05) steps.add(t1.az - t0.az);
            }
        }
        if (steps.n >= 2 && steps.strength() > 0.95) mod.advance = wrap(steps.mean());
    };
    if (advance.n) {
        mod.advance = wrap(advance.mean());
    } else if (!mod.interior.slots.empty() || !mod.has_tip) {
        // No two branched nodes in a row: the roll between nodes shows in the bends.
        advance_from_bends();
    } else {
        // Laterals only at the tip: the divergence that makes the tip's azimuth follow from
        // the axis's length (and its spawn azimuth).
        std::vector<PhaseSample> samples;
        for (int a : axes) {
            const Axis& axis = g.axes[seg(a)];
            const std::vector<int> lat = laterals_of(g, axis.segments.back());
            if (lat.empty()) continue;
            PhaseSample p{static_cast<int>(axis.segments.size()) - 1, m.turn[seg(lat[0])].az, {}};
            if (axis.parent_segment >= 0) p.spawn = m.turn[seg(axis.segments.front())].az;
            samples.push_back(p);
        }
        bool varied = false;
        for (const PhaseSample& p : samples) varied |= p.node != samples.front().node;
        if (varied) {
            mod.advance = regress_divergence(samples);
        } else {
            // Every tip at the same node: the phase drift is the bends' (if any).
            advance_from_bends();
        }
    }

    // Each axis's phase: its first lateral's azimuth moved back to node 0 (a tip-only axis:
    // the tip's), and where the tip's first lateral stands after it.
    Circular tip_offset;
    mod.axis_phase.resize(axes.size());
    for (std::size_t k = 0; k < axes.size(); ++k) {
        const Axis& axis = g.axes[seg(axes[k])];
        const std::size_t n = axis.segments.size();
        for (std::size_t j = 0; j < n; ++j) {
            if (mod.has_tip && j + 1 == n) break;
            const std::vector<int> lat = laterals_of(g, axis.segments[j]);
            if (lat.empty()) continue;
            mod.axis_phase[k] = wrap(m.turn[seg(lat[0])].az - mod.advance * mod.phase_steps(j));
            break;
        }
        const std::vector<int> last = laterals_of(g, axis.segments.back());
        if (mod.has_tip && !last.empty()) {
            const double at_tip = m.turn[seg(last[0])].az;
            if (mod.axis_phase[k])
                tip_offset.add(at_tip - *mod.axis_phase[k] -
                               mod.advance * static_cast<double>(n - 1));
            else
                mod.axis_phase[k] = wrap(at_tip - mod.advance * static_cast<double>(n - 1));
        }
    }
    mod.tip_offset = tip_offset.n ? wrap(tip_offset.mean()) : 0.0;
    // The phases and the divergence once more by least squares over every branched node
    // (one divergence, a phase per axis): the phase from one node and the divergence from
    // differences of neighbours (which add up to the axis's first and last node) carry the
    // noise of those few. A node's azimuth is the mean over its laterals less their slots'
    // offsets. On an example without noise this changes nothing.
    if (!mod.has_tip && advance.n && !mod.interior.slots.empty()) {
        struct Sample {
            double x, r;
        };
        std::vector<std::vector<Sample>> samples(axes.size());
        double pxx = 0.0, pxy = 0.0;
        for (std::size_t k = 0; k < axes.size(); ++k) {
            if (!mod.axis_phase[k]) continue;
            const Axis& axis = g.axes[seg(axes[k])];
            for (std::size_t j = static_cast<std::size_t>(mod.bare); j < axis.segments.size();
                 ++j) {
                if ((static_cast<int>(j) - mod.bare) % mod.period != 0) continue;
                const std::vector<int> lat = laterals_of(g, axis.segments[j]);
                if (lat.empty()) continue;
                Circular node;
                for (std::size_t i = 0; i < lat.size() && i < mod.interior.slots.size(); ++i)
                    node.add(m.turn[seg(lat[i])].az - mod.interior.slots[i].offset);
                const double x = mod.phase_steps(j);
                samples[k].push_back({x, wrap(node.mean() - *mod.axis_phase[k] - mod.advance * x)});
            }
            if (samples[k].empty()) continue;
            double mx = 0.0, mr = 0.0;
            for (const Sample& q : samples[k]) mx += q.x, mr += q.r;
            mx /= static_cast<double>(samples[k].size());
            mr /= static_cast<double>(samples[k].size());
            for (const Sample& q : samples[k]) {
                pxx += (q.x - mx) * (q.x - mx);
                pxy += (q.x - mx) * (q.r - mr);
            }
        }
        const double slope = pxx > 0.0 ? pxy / pxx : 0.0;
        for (std::size_t k = 0; k < axes.size(); ++k) {
            if (samples[k].empty()) continue;
            double mx = 0.0, mr = 0.0;
            for (const Sample& q : samples[k]) mx += q.x, mr += q.r;
            mx /= static_cast<double>(samples[k].size());
            mr /= static_cast<double>(samples[k].size());
            mod.axis_phase[k] = wrap(*mod.axis_phase[k] + mr - slope * mx);
        }
        mod.advance = wrap(mod.advance + slope);
    }
    // Axes without laterals take their phase from their bends (when the first is a bend).
    // The first three bends then do not count among the bends measured from the phase:
    // measured with noise, they share nodes with the first and would agree with it, or
    // turn back from it, and make a bend of noise.
    std::vector<bool> phase_from_bend(axes.size(), false);
    {
        std::vector<std::size_t> unphased;
        for (std::size_t k = 0; k < axes.size(); ++k)
            if (!mod.axis_phase[k]) unphased.push_back(k);
        const bool all = unphased.size() == axes.size();
        for (std::size_t k : unphased) {
            const Axis& axis = g.axes[seg(axes[k])];
            if (!all || axis.segments.size() < 2) continue;
            const Turn& t = m.turn[seg(axis.segments[1])];
            if (t.pitch <= 0.05) continue;
            // Every bend says where node 0's phase is (its azimuth less the divergence up to
            // it); their mean, weighted by the bends' size, carries less noise than one.
            Circular phase;
            for (std::size_t j = 0; j + 1 < axis.segments.size(); ++j) {
                const Turn& b = m.turn[seg(axis.segments[j + 1])];
                if (b.pitch > 0.05) phase.add(b.az - mod.advance * mod.phase_steps(j), b.pitch);
            }
            mod.axis_phase[k] = wrap(phase.mean());
            phase_from_bend[k] = true;
        }
    }

    const TurnMean absolute = bends_of([](int, std::size_t) { return std::optional<double>(0.0); });
    std::map<int, std::size_t> index_of;
    for (std::size_t k = 0; k < axes.size(); ++k) index_of[axes[k]] = k;
    const TurnMean relative = bends_of([&](int a, std::size_t j) -> std::optional<double> {
        const std::size_t k = index_of[a];
        if (phase_from_bend[k] && j < 3) return std::nullopt;
        const std::optional<double>& p = mod.axis_phase[k];
        return p ? *p + mod.advance * mod.phase_steps(j) : 0.0;
    });
    const bool any_phase =
        std::any_of(mod.axis_phase.begin(), mod.axis_phase.end(), [](auto& p) { return bool(p); });
    mod.bend_relative = any_phase && relative.significance() > absolute.significance() * 1.05;
    const TurnMean& chosen = mod.bend_relative ? relative : absolute;
    if (chosen.significance() > 3.0 && chosen.magnitude() > 0.05) {
        mod.bend = chosen.mean();
        mod.bend.az = wrap(mod.bend.az);
    }
    return mod;
}

// How this module's axes start as laterals: their phase, from their spawn azimuth or not.
void fit_phase(Module& mod, const BranchGraph& g, const Measured& m) {
    Circular absolute, relative;
    for (std::size_t k = 0; k < mod.axes.size(); ++k) {
        const Axis& axis = g.axes[static_cast<std::size_t>(mod.axes[k])];
        if (axis.parent_segment < 0 || !mod.axis_phase[k]) continue;
        const std::size_t first = static_cast<std::size_t>(axis.segments.front());
        absolute.add(*mod.axis_phase[k]);
        relative.add(*mod.axis_phase[k] - m.turn[first].az);
    }
    mod.phase_known = absolute.n > 0;
    mod.phase_relative = relative.strength() > absolute.strength() + 1e-6;
    mod.phase = mod.phase_relative ? wrap(relative.mean()) : wrap(absolute.mean());
}

// Each slot's count model, from the laterals it holds in the example: the segments of
// each against the budget its node left it.
void fit_counts(std::vector<Module>& modules, const std::vector<int>& module_of_axis,
                const BranchGraph& g, const Measured& m) {
    for (std::size_t k = 0; k < modules.size(); ++k) {
        Module& parent = modules[k];
        // Per slot: (segments, height, node budget - 1) of each lateral.
        struct Sample {
            int n, h, b;
        };
        std::map<std::pair<bool, std::size_t>, std::vector<Sample>> groups;
        std::map<std::pair<bool, std::size_t>, Circular> phases;
        for (int a : parent.axes) {
            const Axis& axis = g.axes[static_cast<std::size_t>(a)];
            for (std::size_t j = 0; j < axis.segments.size(); ++j) {
                const int s = axis.segments[j];
                const bool tip = parent.has_tip && j + 1 == axis.segments.size();
                const std::vector<int> lat = laterals_of(g, s);
                for (std::size_t i = 0; i < lat.size(); ++i) {
                    const Axis& child = g.axes[static_cast<std::size_t>(
                        g.axis_of[static_cast<std::size_t>(lat[i])])];
                    groups[{tip, i}].push_back({static_cast<int>(child.segments.size()),
                                                g.height[static_cast<std::size_t>(lat[i])],
                                                m.budget[static_cast<std::size_t>(s)] - 1});
                    const int child_axis = g.axis_of[static_cast<std::size_t>(lat[i])];
                    const int c = module_of_axis[static_cast<std::size_t>(child_axis)];
                    if (c < 0) continue;
                    const Module& cm = modules[static_cast<std::size_t>(c)];
                    const auto at = std::find(cm.axes.begin(), cm.axes.end(), child_axis);
                    const std::optional<double>& phase =
                        cm.axis_phase[static_cast<std::size_t>(at - cm.axes.begin())];
                    if (phase)
                        phases[{tip, i}].add(
                            cm.phase_relative ? *phase - m.turn[static_cast<std::size_t>(lat[i])].az
                                              : *phase);
                }
            }
        }
        const Module& child = modules[std::min(k + 1, modules.size() - 1)];
        for (NodePattern* pattern : {&parent.interior, &parent.tip})
            for (Slot& slot : pattern->slots) slot.child_phase = child.phase;
        for (auto& [key, samples] : groups) {
            NodePattern& pattern = key.first ? parent.tip : parent.interior;
            if (key.second >= pattern.slots.size()) continue;
            Slot& slot = pattern.slots[key.second];
            slot.child_phase = phases[key].n ? wrap(phases[key].mean()) : child.phase;
            // The drop d (the lateral's budget is the node's less 1 + d) that lets both its
            // segments and its height follow best.
            long best = -1;
            for (int d = 0; d <= 4; ++d) {
                std::vector<std::pair<int, int>> counts, heights;
                for (const Sample& sample : samples) {
                    const int b = std::max(sample.b - d, 1);
                    counts.emplace_back(sample.n, b);
                    heights.emplace_back(sample.h, b);
                }
                long count_error = 0, height_error = 0;
                const FromBudget count = fit_from_budget(counts, &count_error);
                const FromBudget height = fit_from_budget(heights, &height_error);
                if (best >= 0 && count_error * 4 + height_error >= best) continue;
                best = count_error * 4 + height_error;
                slot.count = count;
                slot.height = height;
                slot.drop = d;
            }
        }
    }
}

bool similar_slots(const NodePattern& a, const NodePattern& b) {
    if (a.nodes == 0 || b.nodes == 0) return true;  // one has no data: nothing contradicts
    if (a.slots.size() != b.slots.size() || a.ks.size() != b.ks.size()) return false;
    for (std::size_t i = 0; i < a.slots.size(); ++i) {
        if (std::abs(a.slots[i].pitch - b.slots[i].pitch) > 8.0) return false;
        if (std::abs(wrap(a.slots[i].offset - b.slots[i].offset)) > 20.0) return false;
        if (std::abs(std::log(a.slots[i].length / b.slots[i].length)) > 0.15) return false;
        if (std::abs(a.slots[i].chance - b.slots[i].chance) > 0.1) return false;
    }
    return true;
}

bool similar(const Module& a, const Module& b) {
    const bool a_branches = a.interior.nodes > 0 || a.tip.nodes > 0;
    const bool b_branches = b.interior.nodes > 0 || b.tip.nodes > 0;
    if (a_branches && b_branches) {
        if (a.has_tip != b.has_tip || a.bare != b.bare || a.period != b.period) return false;
        if (!similar_slots(a.interior, b.interior) || !similar_slots(a.tip, b.tip)) return false;
        if (std::abs(wrap(a.advance - b.advance)) > 20.0) return false;
        if (a.has_tip && std::abs(wrap(a.tip_offset - b.tip_offset)) > 20.0) return false;
    }
    if (a.phase_known && b.phase_known) {
        if (a.phase_relative != b.phase_relative) return false;
        if (std::abs(wrap(a.phase - b.phase)) > 20.0) return false;
    }
    if (a.length_known && b.length_known) {
        if (std::abs(std::log(a.length_ratio / b.length_ratio)) > 0.1) return false;
        if (std::abs(a.bend.pitch - b.bend.pitch) > 5.0) return false;
        if (a.bend.pitch > 0.0 && b.bend.pitch > 0.0 &&
            (a.bend_relative != b.bend_relative || std::abs(wrap(a.bend.az - b.bend.az)) > 30.0))
            return false;
    }
    return true;
}

// ---- writing ------------------------------------------------------------------------------
std::string num(double v) {
    if (std::abs(v) < 1e-4) return "0";  // the grammar's numbers have no exponent
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

std::string FromBudget::text(const std::string& b) const {
    if (kind == Cap) return "min(" + b + "," + std::to_string(cap) + ")";
    if (kind == Share) return "min(" + b + ",floor(" + num(share) + "*(" + b + ")+0.5))";
    return b;
}

// Sums "a" and a number as text, leaving out a zero.
std::string plus(const std::string& a, double v) {
    if (std::abs(v) < 5e-7) return a;
    return v < 0.0 ? a + "-" + num(-v) : a + "+" + num(v);
}

struct Writer {
    std::vector<Module>& modules;
    std::vector<int> child_of;  // per module: the module its laterals are
    std::vector<std::string> defines;
    int unroll = 1;
    Convention convention = Convention::Vertical;

    std::string name(int module) const { return std::string(1, kLetters[module]); }
    // The module an axis starts with: its head rule when it has a bare stretch.
    std::string entry(int module) const {
        if (modules[static_cast<std::size_t>(module)].bare == 0) return name(module);
        return std::string(1, static_cast<char>(std::tolower(kLetters[module])));
    }

    // `/(az)&(angle)` and what the convention does after: `$`, or `\(az)` (roll back).
    std::string turn(const std::string& az, const std::string& angle) const {
        const bool no_az = az == "0";
        std::string out = no_az ? "" : "/(" + az + ")";
        out += "&(" + angle + ")";
        if (convention == Convention::Vertical) return out + "$";
        return no_az ? out : out + "\\(" + az + ")";
    }

    // The phase at a node `steps` divergences on.
    static std::string phase_at(int steps, const std::string& id) {
        return steps == 0 ? "p" : "p+" + std::to_string(steps) + "*dv" + id;
    }

    std::string bend(const Module& mod, const std::string& id, int steps,
                     const std::string& gate) const {
        if (mod.bend.pitch <= 0.0) return "";
        std::string az = num(mod.bend.az);
        if (mod.bend_relative) az = plus(phase_at(steps, id), mod.bend.az);
        return turn(az, num(mod.bend.pitch) + gate);
    }

    // The head rule: the bare stretch in one rewrite, then the axis module.
    std::string head(int k) const {
        const Module& mod = modules[static_cast<std::size_t>(k)];
        const std::string id = std::to_string(k);
        std::string out = entry(k) + "(n,m,l,w,p) : n > 0 -> ";
        for (int j = 0; j < mod.bare; ++j) {
            const std::string along = j == 0 ? "" : "*lr" + id + "^" + std::to_string(j);
            const std::string wider =
                j == 0 ? "" : "*" + num(mod.width_ratio) + "^" + std::to_string(j);
            const std::string gate = j == 0 ? "" : "*(n>" + std::to_string(j) + ")";
            out += "!(w" + wider + ")F(l" + along + gate + ")";
            out += bend(mod, id, j, gate);
        }
        const std::string b = std::to_string(mod.bare);
        out += name(k) + "(n-" + b + ",m-" + b + ",l*" + num(mod.head_ratio) + ",w*" +
               num(mod.width_ratio) + "^" + b + ",p+" + b + "*dv" + id + ")";
        return out;
    }

    void define(const std::string& key, double value, double lo, double hi,
                const std::string& help) {
        char line[256];
        std::snprintf(line, sizeof line, "#define %-5s %-9s # [%s, %s] %s", key.c_str(),
                      num(value).c_str(), num(lo).c_str(), num(hi).c_str(), help.c_str());
        defines.push_back(line);
    }

    // The call of slot i of module k's interior (or tip) laterals at unrolled node j;
    // `gate` multiplies the count (empty: always).
    std::string lateral(int k, bool tip, std::size_t i, int j, int steps, bool stochastic_slots,
                        const std::string& gate) const {
        const Module& mod = modules[static_cast<std::size_t>(k)];
        const int c = child_of[static_cast<std::size_t>(k)];
        const Module& child = modules[static_cast<std::size_t>(c)];
        const NodePattern& pattern = tip ? mod.tip : mod.interior;
        const Slot& slot = pattern.slots[i];
        const std::string id = std::to_string(k);
        const std::string az =
            plus(phase_at(steps, id), slot.offset + (tip ? mod.tip_offset : 0.0));
        const std::string angle =
            tip ? num(slot.pitch) : plus("ba" + id, slot.pitch - pattern.slots[0].pitch);
        const std::string budget = "m-" + std::to_string(j + 1 + slot.drop);
        std::string count = slot.count.text(budget);
        if (!gate.empty()) count = "(" + count + ")*" + gate;
        if (stochastic_slots && slot.chance < 0.999)
            count = "(" + count + ")*(rand(0,1)<" + num(slot.chance) + ")";
        const std::string along = j == 0 ? "" : "*lr" + id + "^" + std::to_string(j);
        const std::string wider =
            j == 0 ? "" : "*" + num(mod.width_ratio) + "^" + std::to_string(j);
        std::string length = "l" + along + "*";
        if (tip)
            length += num(slot.length);
        else
            length +=
                i == 0 ? "cl" + id : "cl" + id + "*" + num(slot.length / pattern.slots[0].length);
        std::string width = "w" + wider + "*" + num(slot.width);
        const std::string phase =
            child.phase_relative ? plus("(" + az + ")", slot.child_phase) : num(slot.child_phase);
        return "[" + turn(az, angle) + entry(c) + "(" + count + "," + slot.height.text(budget) +
               "," + length + "," + width + "," + phase + ")]";
    }

    // One rewrite of module k: `unroll` periods of nodes, each period's first with
    // `laterals` interior laterals (and the tip's at the last node).
    std::string body(int k, int laterals, bool stochastic_slots) const {
        const Module& mod = modules[static_cast<std::size_t>(k)];
        const std::string id = std::to_string(k);
        const int nodes = unroll * mod.period;
        std::string out;
        for (int j = 0; j < nodes; ++j) {
            const int steps = j / mod.period;
            const std::string along = j == 0 ? "" : "*lr" + id + "^" + std::to_string(j);
            const std::string wider =
                j == 0 ? "" : "*" + num(mod.width_ratio) + "^" + std::to_string(j);
            const std::string gate = nodes > 1 ? "*(n>" + std::to_string(j) + ")" : "";
            out += "!(w" + wider + ")F(l" + along + gate + ")";
            // Interior laterals where a node follows (every node without a tip pattern).
            std::string interior_gate;
            if (mod.has_tip)
                interior_gate = "(n>" + std::to_string(j + 1) + ")";
            else if (nodes > 1)
                interior_gate = "(n>" + std::to_string(j) + ")";
            if (j % mod.period == 0)
                for (int i = 0; i < laterals; ++i)
                    out += lateral(k, false, static_cast<std::size_t>(i), j, steps,
                                   stochastic_slots, interior_gate);
            if (mod.has_tip)
                for (std::size_t i = 0; i < mod.tip.slots.size(); ++i)
                    out +=
                        lateral(k, true, i, j, steps, true, "(n==" + std::to_string(j + 1) + ")");
            out += bend(mod, id, steps, gate);
        }
        const std::string u = std::to_string(nodes);
        const std::string turns = std::to_string(unroll);
        out += name(k) + "(n-" + u + ",m-" + u + ",l*lr" + id + (nodes > 1 ? "^" + u : "") + ",w*" +
               num(mod.width_ratio) + (nodes > 1 ? "^" + u : "") + ",p+" +
               (unroll > 1 ? turns + "*" : "") + "dv" + id + ")";
        return out;
    }
};

// The steps a derivation needs when each rewrite draws `unroll` segments of an axis and a
// bare stretch is drawn in one.
int steps_needed(const BranchGraph& g, int unroll, int literal_axis,
                 const std::vector<int>& bare_of_axis, const std::vector<int>& period_of_axis) {
    std::vector<int> step(g.axis_of.size(), 0);
    int most = 0;
    for (std::size_t a = 0; a < g.axes.size(); ++a) {
        const Axis& axis = g.axes[a];
        int start = 1;
        if (axis.parent_segment >= 0)
            start = step[static_cast<std::size_t>(axis.parent_segment)] + 1;
        const bool literal = static_cast<int>(a) == literal_axis;
        const int bare = bare_of_axis[a];
        const int per = unroll * period_of_axis[a];
        for (std::size_t j = 0; j < axis.segments.size(); ++j) {
            const int jj = static_cast<int>(j);
            int s = start + jj / per;
            if (bare > 0) s = jj < bare ? start : start + 1 + (jj - bare) / per;
            if (literal) s = 0;
            step[static_cast<std::size_t>(axis.segments[j])] = s;
            most = std::max(most, s);
        }
    }
    return most;
}

bool is_pipe(const Skeleton& skeleton, const TreeParams& params) {
    Skeleton copy = skeleton;
    apply_pipe_model(copy, static_cast<float>(params.tip_width * 0.5),
                     static_cast<float>(params.pipe_exponent));
    for (std::size_t i = 0; i < copy.segments.size(); ++i) {
        const float want = copy.segments[i].ra, have = skeleton.segments[i].ra;
        if (std::abs(want - have) > 0.02f * std::max(want, 1e-6f)) return false;
    }
    return true;
}

// One inference with one frame convention, with tip patterns or without; `used_tips`
// says whether some module took one.
InferredTemplate infer_with(const ExampleTree& example, const InferSettings& settings,
                            const BranchGraph& g, Convention convention, bool tips,
                            double length_stop, bool* used_tips) {
    const Skeleton& skeleton = example.skeleton;
    const TreeParams source = example.params.value_or(TreeParams{});
    const LSystemParams& source_lsystem = lsystem_params(source);
    const double elasticity = example.params ? source_lsystem.tropism : 0.0;
    const Measured m = measure(skeleton, g, elasticity, convention);
    throw_if_cancelled(settings.cancel);
    InferredTemplate result;

    // The trunk: written out in the axiom when short (a few nodes carry the whole tree's
    // first branches), else a module like the others.
    const int trunk = g.axis_of[static_cast<std::size_t>(g.roots.front())];
    const bool one_root = g.roots.size() == 1;
    const bool literal_trunk =
        one_root && static_cast<int>(g.axes[static_cast<std::size_t>(trunk)].segments.size()) <=
                        kLiteralTrunkNodes;

    // Modules per order; the deepest orders that repeat one pattern fold into one
    // recursive module, and more fold while the rules exceed the limit.
    int max_order = 0;
    for (const Axis& a : g.axes) max_order = std::max(max_order, a.order);
    std::vector<std::vector<int>> by_order(static_cast<std::size_t>(max_order) + 1);
    for (std::size_t a = 0; a < g.axes.size(); ++a)
        if (!(literal_trunk && static_cast<int>(a) == trunk))
            by_order[static_cast<std::size_t>(g.axes[a].order)].push_back(static_cast<int>(a));
    int root_order = max_order;
    for (int r : g.roots)
        root_order = std::min(
            root_order,
            g.axes[static_cast<std::size_t>(g.axis_of[static_cast<std::size_t>(r)])].order);
    const int first_order = literal_trunk ? root_order + 1 : root_order;
    auto build = [&](int fold) {  // orders >= fold share one module
        throw_if_cancelled(settings.cancel);
        std::vector<Module> mods;
        for (int o = first_order; o <= max_order; ++o) {
            std::vector<int> axes;
            for (int q = o; q <= (o >= fold ? max_order : o); ++q)
                axes.insert(axes.end(), by_order[static_cast<std::size_t>(q)].begin(),
                            by_order[static_cast<std::size_t>(q)].end());
            Module mod = fit_module(axes, g, m, tips);
            mod.first_order = o;
            mod.last_order = o >= fold ? max_order : o;
            mods.push_back(mod);
            if (o >= fold) break;
        }
        for (Module& mod : mods) fit_phase(mod, g, m);
        return mods;
    };
    auto rule_count = [](const std::vector<Module>& mods, bool alternatives) {
        int n = 0;
        for (const Module& mod : mods)
            n += (alternatives ? std::max<int>(1, static_cast<int>(mod.interior.ks.size())) : 1) +
                 (mod.bare > 0 ? 1 : 0);
        return n;
    };
    int fold = max_order;
    std::vector<Module> modules = build(fold);
    while (fold > first_order + 1) {
        std::vector<Module> tried = build(fold - 1);
        const Module& folded = tried.back();
        if (!similar(folded, modules[modules.size() - 2]) || !similar(folded, modules.back()))
            break;
        modules = std::move(tried);
        --fold;
    }
    while (fold > first_order && (rule_count(modules, true) > settings.max_rules ||
                                  static_cast<int>(modules.size()) > kMaxModules)) {
        --fold;
        modules = build(fold);
    }
    if (modules.empty()) modules.push_back(Module{});  // a literal trunk without branches
    std::vector<int> module_of_axis(g.axes.size(), -1);
    for (std::size_t k = 0; k < modules.size(); ++k)
        for (int a : modules[k].axes)
            module_of_axis[static_cast<std::size_t>(a)] = static_cast<int>(k);
    fit_counts(modules, module_of_axis, g, m);
    if (length_stop >= 0.0) {
        // Each module draws while its segments stay longer than the given quantile of its
        // lengths in the example (0 the shortest; a little above it where noise shortened
        // a few), every lateral gets the whole budget and every node all its slots: a grammar
        // whose rules stop on a length (`B(l) : l > 0.1`) ends each axis where its lengths
        // fall, which no count from the budget follows.
        for (Module& mod : modules) {
            std::vector<double> lengths;
            for (int a : mod.axes)
                for (int s : g.axes[static_cast<std::size_t>(a)].segments)
                    lengths.push_back(m.length[static_cast<std::size_t>(s)]);
            if (lengths.empty()) continue;
            std::sort(lengths.begin(), lengths.end());
            const double shortest =
                lengths[static_cast<std::size_t>(length_stop * (lengths.size() - 1))];
            if (shortest <= 0.0) continue;
            mod.stop = 0.98 * shortest;
            for (NodePattern* pattern : {&mod.interior, &mod.tip}) {
                for (Slot& slot : pattern->slots) slot.count = slot.height = FromBudget{};
                if (pattern->ks.size() > 1) {
                    int most = 0;
                    for (const auto& kw : pattern->ks) most = std::max(most, kw.first);
                    pattern->ks = {{most, 1.0}};
                }
            }
        }
    }
    *used_tips =
        std::any_of(modules.begin(), modules.end(), [](const Module& mod) { return mod.has_tip; });

    // Segments per rewrite, so the derivation fits the generations a template may have.
    const int literal_axis = literal_trunk ? trunk : -1;
    std::vector<int> bare_of_axis(g.axes.size(), 0), period_of_axis(g.axes.size(), 1);
    for (std::size_t a = 0; a < g.axes.size(); ++a)
        if (module_of_axis[a] >= 0) {
            bare_of_axis[a] = modules[static_cast<std::size_t>(module_of_axis[a])].bare;
            period_of_axis[a] = modules[static_cast<std::size_t>(module_of_axis[a])].period;
        }
    auto steps = [&](int u) {
        return steps_needed(g, u, literal_axis, bare_of_axis, period_of_axis);
    };
    int unroll = 1;
    while (unroll < 16 && steps(unroll) > settings.max_generations) ++unroll;
    const int generations = std::min(settings.max_generations, steps(unroll));
    const bool alternatives = unroll == 1;
    int rules = rule_count(modules, alternatives);
    while (rules > settings.max_rules) {
        // Keep the two most frequent lateral counts of the module with the most.
        Module* widest = nullptr;
        for (Module& mod : modules)
            if (!widest || mod.interior.ks.size() > widest->interior.ks.size()) widest = &mod;
        if (!widest || widest->interior.ks.size() <= 1) break;
        std::sort(widest->interior.ks.begin(), widest->interior.ks.end(),
                  [](auto& a, auto& b) { return a.second > b.second; });
        widest->interior.ks.resize(widest->interior.ks.size() - 1);
        result.generalised.push_back("module " + std::string(1, kLetters[widest - modules.data()]) +
                                     ": the rarest lateral count dropped to stay within " +
                                     std::to_string(settings.max_rules) + " rules");
        rules = rule_count(modules, alternatives);
    }
    result.within_rule_limit = rules <= settings.max_rules;
    if (!result.within_rule_limit)
        result.generalised.push_back("the grammar needs " + std::to_string(rules) +
                                     " rules, more than the limit of " +
                                     std::to_string(settings.max_rules));

    Writer w{modules, {}, {}, unroll, convention};
    for (std::size_t k = 0; k < modules.size(); ++k)
        w.child_of.push_back(static_cast<int>(std::min(k + 1, modules.size() - 1)));
    for (std::size_t k = 0; k < modules.size(); ++k) {
        const Module& mod = modules[k];
        const std::string id = std::to_string(k);
        const std::string what = mod.first_order == mod.last_order
                                     ? "order " + std::to_string(mod.first_order)
                                     : "orders " + std::to_string(mod.first_order) + "+";
        w.define("lr" + id, mod.length_ratio, std::min(0.3, mod.length_ratio * 0.5),
                 std::max(1.2, mod.length_ratio * 1.5),
                 what + ": length of a segment over the one before");
        if (!mod.interior.slots.empty()) {
            w.define("ba" + id, mod.interior.slots[0].pitch, 0.0,
                     std::max(120.0, mod.interior.slots[0].pitch),
                     what + ": branch angle, degrees");
            w.define("dv" + id, mod.advance, -180.0, 180.0,
                     what + ": divergence from one node's branches to the next, degrees");
            w.define("cl" + id, mod.interior.slots[0].length, 0.05,
                     std::max(2.0, mod.interior.slots[0].length * 2.0),
                     what + ": a branch's first segment over its parent segment");
        } else {
            w.define("dv" + id, mod.advance, -180.0, 180.0, what + ": roll per node, degrees");
        }
    }

    // The axiom: each root axis (or the literal trunk) with its start.
    std::string axiom;
    const Module& first = modules.front();
    auto start_args = [&](int axis_index, const Module& mod, int skip) {
        const Axis& axis = g.axes[static_cast<std::size_t>(axis_index)];
        const std::size_t s =
            static_cast<std::size_t>(axis.segments[static_cast<std::size_t>(skip)]);
        double phase = 0.0;
        // The first length from the axis's fitted line where it has no bare stretch.
        double length = m.length[s];
        for (std::size_t k = 0; k < mod.axes.size(); ++k) {
            if (mod.axes[k] != axis_index) continue;
            if (mod.axis_phase[k]) phase = *mod.axis_phase[k];
            if (skip == 0 && mod.bare == 0 && mod.start_length[k]) length = *mod.start_length[k];
        }
        phase += mod.advance * static_cast<double>(skip);
        return "(" + std::to_string(axis.segments.size() - static_cast<std::size_t>(skip)) + "," +
               std::to_string(m.budget[s]) + "," + num(length) + "," + num(m.width[s]) + "," +
               num(wrap(phase)) + ")";
    };
    auto turn_text = [&](const Turn& t) {
        std::string out;
        const bool az = std::abs(t.az) > 5e-7, pitched = std::abs(t.pitch) > 5e-7;
        if (az) out += "/(" + num(t.az) + ")";
        if (pitched) out += "&(" + num(t.pitch) + ")";
        if (convention == Convention::Vertical) return out + "$";
        if (az) out += "\\(" + num(t.az) + ")";
        return out;
    };
    if (literal_trunk) {
        const Axis& axis = g.axes[static_cast<std::size_t>(trunk)];
        for (int s : axis.segments) {
            const std::size_t si = static_cast<std::size_t>(s);
            axiom +=
                turn_text(m.turn[si]) + "!(" + num(m.width[si]) + ")F(" + num(m.length[si]) + ")";
            for (int c : laterals_of(g, s)) {
                const std::size_t ci = static_cast<std::size_t>(c);
                const int child_axis = g.axis_of[ci];
                const int k = std::max(module_of_axis[static_cast<std::size_t>(child_axis)], 0);
                axiom += "[" + turn_text(m.turn[ci]) + w.entry(k) +
                         start_args(child_axis, modules[static_cast<std::size_t>(k)], 0) + "]";
            }
        }
        result.generalised.push_back("the trunk (" + std::to_string(axis.segments.size()) +
                                     " segments) is written out in the axiom as measured");
    } else {
        // Roots of a higher branch depth first, each in brackets; the first root of depth 0
        // (or unknown) last and bare, so that its segments count at depth 0 as they do in
        // the example (a bracket enters a branch).
        std::vector<int> roots;
        for (int r : g.roots)
            if (skeleton.segments[static_cast<std::size_t>(r)].depth > 0) roots.push_back(r);
        int bare_root = -1;
        for (int r : g.roots)
            if (skeleton.segments[static_cast<std::size_t>(r)].depth <= 0) {
                if (bare_root < 0)
                    bare_root = r;
                else
                    roots.push_back(r);
            }
        if (bare_root >= 0) roots.push_back(bare_root);
        for (int r : roots) {
            const std::size_t ri = static_cast<std::size_t>(r);
            const int axis = g.axis_of[ri];
            const bool bracket = r != bare_root;
            // A straight axis (no bend; under tropism, one whose chord is within 2 degrees of
            // its first segment) starts along its chord, root to tip: the first segment
            // alone carries all of its noise, and a tilt at the root moves the whole tree
            // (tropism bends a tilted trunk further).
            Turn start = m.turn[ri];
            const Axis& root_axis = g.axes[static_cast<std::size_t>(axis)];
            if (first.bend.pitch <= 0.0 && root_axis.segments.size() > 1) {
                const glm::dvec3 from(skeleton.segments[ri].a);
                const glm::dvec3 to(
                    skeleton.segments[static_cast<std::size_t>(root_axis.segments.back())].b);
                const glm::dvec3 head = glm::normalize(glm::dvec3(skeleton.segments[ri].b) - from);
                if (glm::length(to - from) > 0.0) {
                    const glm::dvec3 chord = glm::normalize(to - from);
                    if (elasticity == 0.0 || glm::dot(chord, head) > std::cos(2.0 * kDegree))
                        start = solve(Frame{}, chord);
                }
            }
            axiom += (bracket ? "[" : "") + turn_text(start) + w.entry(0) +
                     start_args(axis, first, 0) + (bracket ? "]" : "");
        }
    }

    // The rules.
    std::string grammar;
    grammar += "# Inferred by sylva infer from " + example.format + ": " +
               std::to_string(skeleton.segments.size()) + " segments, " +
               std::to_string(g.axes.size()) + " axes.\n";
    grammar += "# X(n,m,l,w,p): n segments left on the axis, height budget m, segment length l,\n";
    grammar += "# width w, phase p (the azimuth of the next node's first branch).\n";
    for (const std::string& d : w.defines) grammar += d + "\n";
    grammar += "axiom: " + axiom + "\n";
    int written = 0;
    for (std::size_t k = 0; k < modules.size(); ++k) {
        const Module& mod = modules[k];
        if (mod.axes.empty()) continue;
        const std::string head = w.name(static_cast<int>(k)) + "(n,m,l,w,p) : n > 0" +
                                 (mod.stop > 0.0 ? " && l > " + num(mod.stop) : "") + " -> ";
        if (!alternatives || mod.interior.ks.size() <= 1) {
            const int laterals = static_cast<int>(mod.interior.slots.size());
            grammar += head + w.body(static_cast<int>(k), laterals, !alternatives) + "\n";
            ++written;
        } else {
            for (const auto& [count, weight] : mod.interior.ks) {
                grammar +=
                    head + w.body(static_cast<int>(k), count, false) + " : " + num(weight) + "\n";
                ++written;
            }
        }
        if (mod.bare > 0) {
            grammar += w.head(static_cast<int>(k)) + "\n";
            ++written;
        }
        if (mod.interior.ks.size() > 1)
            result.generalised.push_back(
                "module " + w.name(static_cast<int>(k)) +
                ": nodes with different numbers of "
                "branches became " +
                (alternatives ? "weighted alternatives" : "branch chances"));
        if (mod.first_order != mod.last_order)
            result.generalised.push_back("module " + w.name(static_cast<int>(k)) +
                                         " stands for orders " + std::to_string(mod.first_order) +
                                         " to " + std::to_string(mod.last_order) +
                                         " (one recursive rule)");
    }
    result.rules = written;
    result.modules = static_cast<int>(modules.size());
    result.segments_per_step = unroll;
    if (unroll > 1)
        result.generalised.push_back("each rewrite draws " + std::to_string(unroll) +
                                     " segments of an axis, so the tree fits in " +
                                     std::to_string(generations) + " generations");

    // The template: the example's crown, leaf and meshing parameters, the fitted grammar.
    TreeTemplate& tree = result.tree;
    tree.name = settings.name;
    tree.description = "inferred from " + example.format + " (" +
                       std::to_string(skeleton.segments.size()) + " segments) by sylva infer";
    tree.mode = TurtleMode::Abop;
    tree.grammar = grammar;
    tree.params = source;
    LSystemParams& lsystem = tree.params.blocks.edit<LSystemParams>();
    lsystem.generations = generations;
    lsystem.tropism = elasticity;
    lsystem.jitter = 0.0;
    lsystem.bend = 0.0;
    lsystem.width_variation = 0.0;
    tree.params.tropism_variation = 0.0;
    tree.params.age = 1.0;
    const bool have_widths = std::any_of(skeleton.segments.begin(), skeleton.segments.end(),
                                         [](const Segment& s) { return s.ra > 0.0f; });
    if (!have_widths || (example.params && is_pipe(skeleton, source))) {
        tree.width_model = WidthModel::Pipe;
        if (!have_widths) {
            double height = 0.0;
            for (const Segment& s : skeleton.segments) height = std::max<double>(height, s.b.y);
            tree.params.tip_width = std::clamp(height * 0.004, 0.005, 0.1);
        }
    } else {
        tree.width_model = WidthModel::Explicit;
    }
    if (!example.params) {
        // Crown spheres about as far apart as the tips are.
        double tip_spacing = 0.0;
        int n = 0;
        for (std::size_t i = 0; i < skeleton.segments.size(); ++i)
            if (g.children[i].empty()) {
                tip_spacing += m.length[i];
                ++n;
            }
        tree.params.sphere_diameter = std::clamp(n ? 3.0 * tip_spacing / n : 0.3, 0.05, 3.0);
        result.generalised.push_back("crown and leaves estimated: sphere_diameter " +
                                     num(tree.params.sphere_diameter));
    } else {
        result.generalised.push_back("crown, leaf and meshing parameters carried over");
    }
    for (const std::string& note : example.notes) result.dropped.push_back(note);
    if (elasticity != 0.0 || source_lsystem.jitter != 0.0 || source_lsystem.bend != 0.0)
        result.generalised.push_back("angles are measured against tropism " + num(elasticity) +
                                     "; the example's noise (jitter, bend) is averaged out");

    std::ostringstream header;
    header << "# " << tree.description << ".\n"
           << "# Each module is one kind of axis; the #define sliders change what varies\n"
           << "# smoothly (length ratios, branch and divergence angles). docs/infer.md says how.\n";
    result.text = template_file_text(tree, header.str() + "name = \"\"\n");
    return result;
}

// How far a regrown skeleton is from the example: the relative differences of the fit
// report's figures and the Hausdorff distance over the height, summed.
double misfit(const SkeletonFigures& want, const std::vector<glm::vec3>& want_points, float spacing,
              const Skeleton& grown) {
    const SkeletonFigures have = skeleton_figures(grown);
    auto diff = [](double a, double b) {
        if (a == 0.0) return b == 0.0 ? 0.0 : 1.0;
        return std::abs(b - a) / std::abs(a);
    };
    double depth = 0.0;
    const std::size_t depths = std::max(want.per_depth.size(), have.per_depth.size());
    for (std::size_t d = 0; d < depths; ++d)
        depth = std::max(depth, diff(d < want.per_depth.size() ? double(want.per_depth[d]) : 0.0,
                                     d < have.per_depth.size() ? double(have.per_depth[d]) : 0.0));
    const double height = std::max(want.height, 1e-6);
    return diff(double(want.segments), double(have.segments)) +
           diff(want.total_length, have.total_length) + diff(want.height, have.height) +
           diff(want.crown_width, have.crown_width) + 0.5 * depth +
           hausdorff_distance(want_points, sample_skeleton(grown, spacing)) / height;
}

// Tries the inferred template under a few more tropism elasticities (negative bends every
// axis up, positive down, after each F) and keeps the one that regrows the example
// closest, rewriting the template text's `tropism` line. Axes that curve with no repeated
// pattern (a tree grown towards attraction points) straighten in the rules; a tropism
// puts the curve back into the envelope's height and width. Throws Cancelled.
void refine_tropism(InferredTemplate& best, double& best_misfit, const SkeletonFigures& want,
                    const std::vector<glm::vec3>& want_points, float spacing,
                    const CancelFlag& cancel) {
    // A regrowth within a hundredth on the sum of figures already has its curves.
    if (best_misfit < 0.01) return;
    const double start = lsystem_params(best.tree.params).tropism;
    double chosen = start;
    // Only where the regrowth is not nearer the example's points anyway: a tropism trades
    // the figures of the envelope against the place of every branch.
    double nearest = 0.0;
    try {
        GrowthContext context;
        context.cancel = cancel;
        nearest =
            hausdorff_distance(want_points, sample_skeleton(grow(best.tree, context), spacing));
    } catch (const InputError&) {
        return;
    }
    for (double step : {-0.2, -0.1, -0.05, -0.02, 0.02, 0.05, 0.1, 0.2}) {
        throw_if_cancelled(cancel);
        TreeTemplate tree = best.tree;
        tree.params.blocks.edit<LSystemParams>().tropism = start + step;
        GrowthContext context;
        context.cancel = cancel;
        try {
            const Skeleton grown = grow(tree, context);
            const double score = misfit(want, want_points, spacing, grown);
            const double distance =
                hausdorff_distance(want_points, sample_skeleton(grown, spacing));
            if (score < best_misfit - 1e-9 && distance <= nearest) {
                best_misfit = score;
                nearest = distance;
                chosen = start + step;
            }
        } catch (const InputError&) {
            // Over a cost limit: this elasticity is not a candidate.
        }
    }
    if (chosen == start) return;
    best.tree.params.blocks.edit<LSystemParams>().tropism = chosen;
    static const std::regex line(R"((^|\n)tropism = [^\n]*)");
    best.text = std::regex_replace(best.text, line, "$1tropism = " + num(chosen),
                                   std::regex_constants::format_first_only);
    best.generalised.push_back("tropism " + num(chosen) +
                               " bends the straight axes of the rules as the example's curve");
}

}  // namespace

InferredTemplate infer_template(const ExampleTree& example, const InferSettings& settings) {
    const Skeleton& skeleton = example.skeleton;
    if (skeleton.segments.empty()) throw InputError("the example tree has no segments");
    const BranchGraph g = build_branch_graph(skeleton, example.continuation);
    // The example with its orders as branch depths, as a regrown tree counts them.
    Skeleton ordered = skeleton;
    for (std::size_t i = 0; i < ordered.segments.size(); ++i)
        ordered.segments[i].depth = g.axes[static_cast<std::size_t>(g.axis_of[i])].order;
    const SkeletonFigures want = skeleton_figures(ordered);
    const float spacing = static_cast<float>(std::max(want.height, 1e-3) / 200.0);
    const std::vector<glm::vec3> want_points = sample_skeleton(ordered, spacing);

    // Each frame convention, with tip patterns and (where some module took one) without,
    // kept when it regrows the example closer: no one model fits every grammar, and a
    // regrowth is cheap next to reading the example.
    std::optional<InferredTemplate> best;
    double best_misfit = 0.0;
    Convention best_convention = Convention::Vertical;
    bool best_tips = true;
    auto consider = [&](Convention convention, bool tips, double length_stop, bool* used_tips) {
        InferredTemplate candidate =
            infer_with(example, settings, g, convention, tips, length_stop, used_tips);
        GrowthContext context;
        context.cancel = settings.cancel;
        double score = 1e9;
        try {
            score = misfit(want, want_points, spacing, grow(candidate.tree, context));
        } catch (const InputError&) {
            // A grammar over a cost limit regrows nothing: another candidate wins.
        }
        if (!best || score < best_misfit) {
            best = std::move(candidate);
            best_misfit = score;
            best_convention = convention;
            best_tips = tips;
        }
    };
    for (Convention convention : {Convention::Vertical, Convention::Minimal}) {
        for (bool tips : {true, false}) {
            bool used_tips = false;
            consider(convention, tips, -1.0, &used_tips);
            if (!used_tips) break;  // without tips it would be the same
        }
    }
    // The closest of those once more with axes that stop on a length, only where it misses.
    if (best_misfit >= 0.01) {
        const Convention convention = best_convention;
        const bool tips = best_tips;
        for (double quantile : {0.0, 0.03, 0.06}) {
            bool used_tips = false;
            consider(convention, tips, quantile, &used_tips);
        }
    }
    refine_tropism(*best, best_misfit, want, want_points, spacing, settings.cancel);
    return std::move(*best);
}

}  // namespace sylva
