#include "infer/rule_inference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <sstream>

#include "core/errors.h"
#include "core/pipe_model.h"
#include "infer/branch_graph.h"
#include "tree/template_file.h"

namespace sylva {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr char kLetters[] = "ABCDEGHIJKMN";  // module names: capitals the turtle ignores
constexpr int kMaxModules = 12;
// A trunk of at most this many nodes is written out in the axiom, node by node, with its
// first-order branches as calls: it is where the example differs most from any rule and
// where an error shows most.
constexpr int kLiteralTrunkNodes = 6;

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
Frame turned(Frame f, const Turn& t) {
    roll(f, -t.az);
    pitch(f, t.pitch);
    roll_to_vertical(f);
    return f;
}

// ---- statistics -------------------------------------------------------------------------
struct Circular {
    double s = 0.0, c = 0.0;
    int n = 0;
    void add(double degrees) {
        s += std::sin(degrees * kDegree);
        c += std::cos(degrees * kDegree);
        ++n;
    }
    double mean() const { return n ? std::atan2(s, c) / kDegree : 0.0; }
    double strength() const { return n ? std::hypot(s, c) / n : 0.0; }
};
struct Mean {
    double sum = 0.0;
    int n = 0;
    void add(double v) {
        sum += v;
        ++n;
    }
    double mean(double fallback = 0.0) const { return n ? sum / n : fallback; }
};
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

// ---- what is measured per segment --------------------------------------------------------
struct Measured {
    std::vector<double> length, width;  // width: diameter at the segment's start
    std::vector<Turn> turn;             // from the parent's end frame (a root: the start frame)
    std::vector<int> budget;            // the height budget m the module has at the segment
    std::vector<int> node;              // index on its axis
};

Measured measure(const Skeleton& skeleton, const BranchGraph& g, double elasticity) {
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
        Frame f = turned(from, m.turn[i]);
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
struct Slot {
    double offset = 0.0;  // azimuth after the node's first lateral, degrees
    double pitch = 0.0;   // branch angle, degrees
    double length = 1.0;  // first segment's length over the parent segment's
    double width = 1.0;   // and its width over the parent's
    double chance = 1.0;  // probability that a node has this lateral (k > index)
};

struct Module {
    std::vector<int> axes;                   // the example's axes it stands for
    int first_order = 0, last_order = 0;     // orders it covers (recursive when more)
    std::vector<std::pair<int, double>> ks;  // lateral counts with their frequencies
    std::vector<Slot> slots;
    double advance = 0.0;  // divergence: phase change from one node to the next, degrees
    Turn bend;             // turn before the next segment of the axis
    double length_ratio = 1.0, width_ratio = 1.0;
    int budget_drop = 0;  // a lateral's height budget: the node's minus 1 minus this
    // How this module's axes are as laterals: their first phase (absolute, or their spawn
    // azimuth plus this) and their segment count (min(budget, cap), or budget * share).
    bool phase_relative = false;
    double phase = 0.0;
    int cap = 0;  // 0: none
    bool by_share = false;
    double share = 1.0;
    int nodes = 0;
    // Nodes without branches at the base of every axis (a bare stretch), drawn by a head rule.
    int bare = 0;
    double head_ratio = 1.0;  // the first branched segment's length over the axis's first
};

// The phase of an axis: its first lateral's azimuth, moved back to node 0.
std::optional<double> axis_phase(const Axis& axis, const BranchGraph& g, const Measured& m,
                                 double advance) {
    for (std::size_t j = 0; j < axis.segments.size(); ++j) {
        const std::vector<int> lat = laterals_of(g, axis.segments[j]);
        if (!lat.empty())
            return wrap(m.turn[static_cast<std::size_t>(lat.front())].az -
                        advance * static_cast<double>(j));
    }
    return std::nullopt;
}

Module fit_module(const std::vector<int>& axes, const BranchGraph& g, const Measured& m,
                  int skip_root_nodes) {
    Module mod;
    mod.axes = axes;
    std::map<int, int> k_count;
    std::vector<Circular> offsets;
    std::vector<Mean> pitches;
    std::vector<Ratio> lengths, widths;
    Circular advance, bend_az;
    Mean bend_pitch, drop;
    Ratio length_ratio, width_ratio;
    int non_tips = 0;
    // The bare stretch: leading nodes without laterals, where most branched axes agree.
    std::map<int, int> leading;
    int branched = 0;
    for (int a : axes) {
        const Axis& axis = g.axes[static_cast<std::size_t>(a)];
        for (std::size_t j = 0; j < axis.segments.size(); ++j)
            if (!laterals_of(g, axis.segments[j]).empty()) {
                ++leading[static_cast<int>(j)];
                ++branched;
                break;
            }
    }
    for (const auto& [count, n] : leading)
        if (count > 0 && n * 10 >= branched * 7) mod.bare = count;
    Ratio head_ratio;
    for (int a : axes) {
        const Axis& axis = g.axes[static_cast<std::size_t>(a)];
        if (mod.bare > 0 && static_cast<int>(axis.segments.size()) > mod.bare)
            head_ratio.add(m.length[static_cast<std::size_t>(
                               axis.segments[static_cast<std::size_t>(mod.bare)])],
                           m.length[static_cast<std::size_t>(axis.segments[0])]);
    }
    mod.head_ratio = head_ratio.mean();
    for (int a : axes) {
        const Axis& axis = g.axes[static_cast<std::size_t>(a)];
        double previous_first = 0.0;
        bool have_previous = false;
        for (std::size_t j = 0; j < axis.segments.size(); ++j) {
            const int s = axis.segments[j];
            const std::size_t si = static_cast<std::size_t>(s);
            if (axis.parent_segment < 0 && static_cast<int>(j) < skip_root_nodes) continue;
            if (static_cast<int>(j) < mod.bare) continue;
            ++mod.nodes;
            const int next = g.continuation[si];
            if (next >= 0) {
                const Turn& t = m.turn[static_cast<std::size_t>(next)];
                if (t.pitch > 1e-6) bend_az.add(t.az);
                bend_pitch.add(t.pitch);
                length_ratio.add(m.length[static_cast<std::size_t>(next)], m.length[si]);
                width_ratio.add(m.width[static_cast<std::size_t>(next)], m.width[si]);
            }
            const std::vector<int> lat = laterals_of(g, s);
            if (static_cast<int>(j) < mod.bare) continue;
            if (g.children[si].empty()) {
                have_previous = false;
                continue;
            }
            ++non_tips;
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
                drop.add(m.budget[si] - 1 - g.height[c]);
            }
            if (!lat.empty()) {
                if (have_previous) advance.add(first - previous_first);
                previous_first = first;
            }
            have_previous = !lat.empty();
        }
    }
    // Lateral counts: those seen at 5 % of the nodes or more, with their frequencies.
    for (const auto& [k, n] : k_count)
        if (n * 20 >= non_tips) mod.ks.emplace_back(k, static_cast<double>(n));
    if (mod.ks.empty() && !k_count.empty()) mod.ks.emplace_back(k_count.rbegin()->first, 1.0);
    double total = 0.0;
    for (auto& [k, w] : mod.ks) total += w;
    for (auto& [k, w] : mod.ks) w /= total;
    int kmax = 0;
    for (auto& [k, w] : mod.ks) kmax = std::max(kmax, k);
    mod.slots.resize(static_cast<std::size_t>(kmax));
    for (std::size_t i = 0; i < mod.slots.size() && i < offsets.size(); ++i) {
        Slot& slot = mod.slots[i];
        slot.offset = i == 0 ? 0.0 : wrap(offsets[i].mean());
        slot.pitch = pitches[i].mean();
        slot.length = lengths[i].mean();
        slot.width = widths[i].mean();
        double more = 0.0;
        for (auto& [k, w] : mod.ks)
            if (k > static_cast<int>(i)) more += w;
        slot.chance = more;
    }
    mod.advance = advance.n ? wrap(advance.mean()) : 0.0;
    // Bends in scattered directions cancel out: the mean bend is the mean pitch times how
    // much the bend directions agree.
    mod.bend = {bend_az.mean(), bend_pitch.mean() * bend_az.strength()};
    if (mod.bend.pitch < 0.05) mod.bend = {};
    mod.length_ratio = length_ratio.mean();
    mod.width_ratio = width_ratio.mean();
    mod.budget_drop = std::max(0, static_cast<int>(std::lround(drop.mean(0.0))));
    return mod;
}

// How this module's axes start as laterals: their phase and segment count.
void fit_as_lateral(Module& mod, const Module& parent, const BranchGraph& g, const Measured& m) {
    Circular absolute, relative;
    std::vector<std::pair<int, int>> count_budget;
    for (int a : mod.axes) {
        const Axis& axis = g.axes[static_cast<std::size_t>(a)];
        if (axis.parent_segment < 0) continue;
        const std::size_t first = static_cast<std::size_t>(axis.segments.front());
        if (std::optional<double> p = axis_phase(axis, g, m, mod.advance)) {
            absolute.add(*p);
            relative.add(*p - m.turn[first].az);
        }
        const int budget =
            m.budget[static_cast<std::size_t>(axis.parent_segment)] - 1 - parent.budget_drop;
        count_budget.emplace_back(static_cast<int>(axis.segments.size()), std::max(budget, 1));
    }
    mod.phase_relative = relative.strength() > absolute.strength() + 1e-6;
    mod.phase = mod.phase_relative ? wrap(relative.mean()) : wrap(absolute.mean());
    // Segment count: min(budget, cap) or a share of the budget, whichever errs less.
    auto error_cap = [&](int cap) {
        long e = 0;
        for (auto [n, b] : count_budget) e += std::abs(n - (cap ? std::min(b, cap) : b));
        return e;
    };
    long best = error_cap(0);
    mod.cap = 0;
    std::vector<int> candidates;
    for (auto [n, b] : count_budget) candidates.push_back(n);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (int c : candidates) {
        const long e = error_cap(c);
        if (e < best) {
            best = e;
            mod.cap = c;
        }
    }
    double sn = 0.0, sb = 0.0;
    for (auto [n, b] : count_budget) {
        sn += n;
        sb += b;
    }
    if (sb > 0.0) {
        mod.share = std::min(1.0, sn / sb);
        long e = 0;
        for (auto [n, b] : count_budget)
            e += std::abs(n - std::min(b, static_cast<int>(std::floor(mod.share * b + 0.5))));
        if (e < best) mod.by_share = true;
    }
}

bool similar(const Module& a, const Module& b) {
    if (a.slots.size() != b.slots.size() || a.ks.size() != b.ks.size()) return false;
    if (a.bare != b.bare) return false;
    if (a.phase_relative != b.phase_relative || a.cap != b.cap || a.by_share != b.by_share)
        return false;
    if (std::abs(wrap(a.phase - b.phase)) > 20.0) return false;
    if (std::abs(wrap(a.advance - b.advance)) > 20.0) return false;
    if (std::abs(std::log(a.length_ratio / b.length_ratio)) > 0.1) return false;
    if (std::abs(a.bend.pitch - b.bend.pitch) > 5.0) return false;
    for (std::size_t i = 0; i < a.slots.size(); ++i) {
        if (std::abs(a.slots[i].pitch - b.slots[i].pitch) > 8.0) return false;
        if (std::abs(wrap(a.slots[i].offset - b.slots[i].offset)) > 20.0) return false;
        if (std::abs(std::log(a.slots[i].length / b.slots[i].length)) > 0.15) return false;
        if (std::abs(a.slots[i].chance - b.slots[i].chance) > 0.1) return false;
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

    std::string name(int module) const { return std::string(1, kLetters[module]); }
    // The module an axis starts with: its head rule when it has a bare stretch.
    std::string entry(int module) const {
        if (modules[static_cast<std::size_t>(module)].bare == 0) return name(module);
        return std::string(1, static_cast<char>(std::tolower(kLetters[module])));
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
            if (mod.bend.pitch > 0.0)
                out += "/(" + num(mod.bend.az) + ")&(" + num(mod.bend.pitch) + gate + ")$";
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

    // The lateral's call for slot i of module `k` at unrolled node j.
    std::string lateral(int k, std::size_t i, int j, bool stochastic_slots) const {
        const Module& mod = modules[static_cast<std::size_t>(k)];
        const Module& child =
            modules[static_cast<std::size_t>(child_of[static_cast<std::size_t>(k)])];
        const Slot& slot = mod.slots[i];
        const std::string id = std::to_string(k);
        std::string az = j == 0 ? "p" : "p+" + std::to_string(j) + "*dv" + id;
        az = plus(az, slot.offset);
        const std::string angle = plus("ba" + id, slot.pitch - mod.slots[0].pitch);
        std::string budget = "m-" + std::to_string(j + 1 + mod.budget_drop);
        std::string count;
        if (child.by_share)
            count = "min(" + budget + ",floor(" + num(child.share) + "*(" + budget + ")+0.5))";
        else if (child.cap > 0)
            count = "min(" + budget + "," + std::to_string(child.cap) + ")";
        else
            count = budget;
        if (unroll > 1) count = "(" + count + ")*(n>" + std::to_string(j) + ")";
        if (stochastic_slots && slot.chance < 0.999)
            count = "(" + count + ")*(rand(0,1)<" + num(slot.chance) + ")";
        const std::string along = j == 0 ? "" : "*lr" + id + "^" + std::to_string(j);
        const std::string wider =
            j == 0 ? "" : "*" + num(mod.width_ratio) + "^" + std::to_string(j);
        std::string length =
            "l" + along + "*" +
            (i == 0 ? "cl" + id : "cl" + id + "*" + num(slot.length / mod.slots[0].length));
        std::string width = "w" + wider + "*" + num(slot.width);
        const std::string phase =
            child.phase_relative ? plus("(" + az + ")", child.phase) : num(child.phase);
        return "[/(" + az + ")&(" + angle + ")$" + entry(child_of[static_cast<std::size_t>(k)]) +
               "(" + count + "," + budget + "," + length + "," + width + "," + phase + ")]";
    }

    std::string body(int k, int laterals, bool stochastic_slots) const {
        const Module& mod = modules[static_cast<std::size_t>(k)];
        const std::string id = std::to_string(k);
        std::string out;
        for (int j = 0; j < unroll; ++j) {
            const std::string along = j == 0 ? "" : "*lr" + id + "^" + std::to_string(j);
            const std::string wider =
                j == 0 ? "" : "*" + num(mod.width_ratio) + "^" + std::to_string(j);
            const std::string gate = unroll > 1 ? "*(n>" + std::to_string(j) + ")" : "";
            out += "!(w" + wider + ")F(l" + along + gate + ")";
            for (int i = 0; i < laterals; ++i)
                out += lateral(k, static_cast<std::size_t>(i), j, stochastic_slots);
            if (mod.bend.pitch > 0.0) {
                out += "/(" + num(mod.bend.az) + ")&(" + num(mod.bend.pitch) + gate + ")$";
            }
        }
        const std::string u = std::to_string(unroll);
        out += name(k) + "(n-" + u + ",m-" + u + ",l*lr" + id + (unroll > 1 ? "^" + u : "") +
               ",w*" + num(mod.width_ratio) + (unroll > 1 ? "^" + u : "") + ",p+" +
               (unroll > 1 ? u + "*" : "") + "dv" + id + ")";
        return out;
    }
};

// The steps a derivation needs when each rewrite draws `unroll` segments of an axis.
int steps_needed(const BranchGraph& g, int unroll, int literal_axis) {
    std::vector<int> step(g.axis_of.size(), 0);
    int most = 0;
    for (const Axis& axis : g.axes) {
        int start = 1;
        if (axis.parent_segment >= 0)
            start = step[static_cast<std::size_t>(axis.parent_segment)] + 1;
        const bool literal = &axis - g.axes.data() == literal_axis;
        for (std::size_t j = 0; j < axis.segments.size(); ++j) {
            const int s = literal ? 0 : start + static_cast<int>(j) / unroll;
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

}  // namespace

InferredTemplate infer_template(const ExampleTree& example, const InferSettings& settings) {
    const Skeleton& skeleton = example.skeleton;
    if (skeleton.segments.empty()) throw InputError("the example tree has no segments");
    const BranchGraph g = build_branch_graph(skeleton, example.continuation);
    const TreeParams source = example.params.value_or(TreeParams{});
    const double elasticity = example.params ? source.tropism : 0.0;
    const Measured m = measure(skeleton, g, elasticity);
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
            Module mod = fit_module(axes, g, m, 0);
            mod.first_order = o;
            mod.last_order = o >= fold ? max_order : o;
            mods.push_back(mod);
            if (o >= fold) break;
        }
        for (std::size_t k = 0; k < mods.size(); ++k) {
            const Module& parent = k == 0 ? mods[0] : mods[k - 1];
            fit_as_lateral(mods[k], parent, g, m);
        }
        return mods;
    };
    auto rule_count = [](const std::vector<Module>& mods, bool alternatives) {
        int n = 0;
        for (const Module& mod : mods)
            n += (alternatives ? std::max<int>(1, static_cast<int>(mod.ks.size())) : 1) +
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

    // Segments per rewrite, so the derivation fits the generations a template may have.
    const int literal_axis = literal_trunk ? trunk : -1;
    int unroll = 1;
    while (unroll < 16 && steps_needed(g, unroll, literal_axis) > settings.max_generations)
        ++unroll;
    const int generations =
        std::min(settings.max_generations, steps_needed(g, unroll, literal_axis));
    const bool alternatives = unroll == 1;
    int rules = rule_count(modules, alternatives);
    while (rules > settings.max_rules) {
        // Keep the two most frequent lateral counts of the module with the most.
        Module* widest = nullptr;
        for (Module& mod : modules)
            if (!widest || mod.ks.size() > widest->ks.size()) widest = &mod;
        if (!widest || widest->ks.size() <= 1) break;
        std::sort(widest->ks.begin(), widest->ks.end(),
                  [](auto& a, auto& b) { return a.second > b.second; });
        widest->ks.resize(widest->ks.size() - 1);
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

    Writer w{modules, {}, {}, unroll};
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
        if (!mod.slots.empty()) {
            w.define("ba" + id, mod.slots[0].pitch, 0.0, std::max(120.0, mod.slots[0].pitch),
                     what + ": branch angle, degrees");
            w.define("dv" + id, mod.advance, -180.0, 180.0,
                     what + ": divergence from one node's branches to the next, degrees");
            w.define("cl" + id, mod.slots[0].length, 0.05, std::max(2.0, mod.slots[0].length * 2.0),
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
        const double phase = axis_phase(axis, g, m, mod.advance).value_or(0.0) +
                             mod.advance * static_cast<double>(skip);
        return "(" + std::to_string(axis.segments.size() - static_cast<std::size_t>(skip)) + "," +
               std::to_string(m.budget[s]) + "," + num(m.length[s]) + "," + num(m.width[s]) + "," +
               num(wrap(phase)) + ")";
    };
    auto turn_text = [](const Turn& t) {
        std::string out;
        if (std::abs(t.az) > 5e-7) out += "/(" + num(t.az) + ")";
        if (std::abs(t.pitch) > 5e-7) out += "&(" + num(t.pitch) + ")";
        return out + "$";
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
                const Axis& lateral = g.axes[static_cast<std::size_t>(child_axis)];
                const int k = std::clamp(lateral.order - first_order, 0,
                                         static_cast<int>(modules.size()) - 1);
                axiom += "[" + turn_text(m.turn[ci]) + w.entry(k) +
                         start_args(child_axis, modules[static_cast<std::size_t>(k)], 0) + "]";
            }
        }
        result.generalised.push_back("the trunk (" + std::to_string(axis.segments.size()) +
                                     " segments) is written out in the axiom as measured");
    } else {
        for (int r : g.roots) {
            const std::size_t ri = static_cast<std::size_t>(r);
            const int axis = g.axis_of[ri];
            const bool bracket = skeleton.segments[ri].depth > 0;
            axiom += (bracket ? "[" : "") + turn_text(m.turn[ri]) + w.entry(0) +
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
        const std::string head = w.name(static_cast<int>(k)) + "(n,m,l,w,p) : n > 0 -> ";
        if (!alternatives || mod.ks.size() <= 1) {
            const int laterals = static_cast<int>(mod.slots.size());
            grammar += head + w.body(static_cast<int>(k), laterals, !alternatives) + "\n";
            ++written;
        } else {
            for (const auto& [count, weight] : mod.ks) {
                grammar +=
                    head + w.body(static_cast<int>(k), count, false) + " : " + num(weight) + "\n";
                ++written;
            }
        }
        if (mod.bare > 0) {
            grammar += w.head(static_cast<int>(k)) + "\n";
            ++written;
        }
        if (mod.ks.size() > 1)
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
    tree.params.generations = generations;
    tree.params.tropism = elasticity;
    tree.params.jitter = 0.0;
    tree.params.bend = 0.0;
    tree.params.width_variation = 0.0;
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
    if (elasticity != 0.0 || source.jitter != 0.0 || source.bend != 0.0)
        result.generalised.push_back("angles are measured against tropism " + num(elasticity) +
                                     "; the example's noise (jitter, bend) is averaged out");

    std::ostringstream header;
    header << "# " << tree.description << ".\n"
           << "# Each module is one kind of axis; the #define sliders change what varies\n"
           << "# smoothly (length ratios, branch and divergence angles). docs/infer.md says how.\n";
    result.text = template_file_text(tree, header.str() + "name = \"\"\n");
    return result;
}

}  // namespace sylva
