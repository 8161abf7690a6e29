#include "tree/branch_prisms.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <numeric>
#include <queue>
#include <tuple>

namespace sylva {
namespace {

// A child continues its parent's axis within this angle of the parent's direction.
constexpr float kContinueCos = 0.5f;  // 60 degrees

glm::vec3 unit_direction(const Segment& s) {
    const glm::vec3 d = s.b - s.a;
    const float length = glm::length(d);
    return length > 0.0f ? d / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

// The sides of an axis of base radius `radius`: max_sides for the thickest, falling with
// the radius (every prism's facets about as wide as the thickest's), and no more than keep
// the polygon within half the look's `tolerance` of the round branch (a radius r polygon of
// n sides strays r (1 - cos(pi / n))): a twig a pixel or two across reads the same as a
// triangle or a hexagon, and the triangles it saves draw more twigs.
int sides_for(float radius, float thickest, int max_sides, float tolerance) {
    const float share = thickest > 0.0f ? radius / thickest : 1.0f;
    int sides = static_cast<int>(std::lround(static_cast<float>(max_sides) * share));
    const float stray = 0.5f * tolerance;
    if (radius > stray) {
        const float enough = std::numbers::pi_v<float> / std::acos(1.0f - stray / radius);
        sides = std::min(sides, static_cast<int>(std::ceil(enough)));
    } else {
        sides = 3;
    }
    return std::clamp(sides, 3, max_sides);
}

// A branch that does not fit at the look's tolerance is tried at twice and four times it;
// beyond, only a root is drawn (as coarse as that makes it).
constexpr int kCoarserTries = 3;

constexpr float kGoldenAngle = 2.39996323f;  // radians

// A short point's ring lies this many of the end's radii before the end: about where the
// round end of the full-detail branch starts to close.
constexpr float kShortTipLength = 0.5f;

// The axis simplified to `tolerance`; with `short_tip`, a pointed end whose last segment is
// longer than kShortTipSegment times the end's radius gets a ring kShortTipLength radii
// before the end, so that only that much of it narrows to the point.
TubeAxis drawn_axis(const TubeAxis& axis, float tolerance, bool short_tip) {
    TubeAxis out = simplify_axis(axis, tolerance);
    const std::size_t n = out.points.size();
    if (!short_tip || !out.pointed || n < 2) return out;
    const glm::vec3 a = out.points[n - 2], b = out.points[n - 1];
    const float ra = out.radii[n - 2], rb = out.radii[n - 1];
    const float length = glm::distance(a, b);
    if (length <= kShortTipSegment * rb) return out;
    const float t = 1.0f - kShortTipLength * rb / length;  // where the ring lies, a to b
    out.points.insert(out.points.end() - 1, a + t * (b - a));
    out.radii.insert(out.radii.end() - 1, ra + t * (rb - ra));
    return out;
}

// The triangles of `axis` drawn as tube_pieces() cuts it.
std::size_t axis_triangles(const TubeAxis& axis, int sides) {
    std::size_t triangles = 0;
    for (const TubeAxis& piece : tube_pieces(axis, sides))
        triangles += tube_triangles(piece.points.size(), sides, piece.pointed);
    return triangles;
}

}  // namespace

BranchAxes branch_axes(const Skeleton& skeleton, std::span<const std::uint8_t> shown,
                       float min_radius) {
    const std::vector<Segment>& segments = skeleton.segments;
    const std::size_t n = segments.size();
    BranchAxes out;
    if (n == 0) return out;
    glm::vec3 low(segments[0].a), high(segments[0].a);
    for (const Segment& s : segments) {
        low = glm::min(low, glm::min(s.a, s.b));
        high = glm::max(high, glm::max(s.a, s.b));
    }
    const glm::vec3 size = high - low;
    out.extent = std::max({size.x, size.y, size.z});

    // A segment drawn again (brackets that redraw a branch, as `[F][FF]` does) would give a
    // second prism lying in the first: of segments from one point in one direction only the
    // longest is drawn (the others lie inside it).
    std::vector<std::uint8_t> drawn(shown.begin(), shown.end());
    {
        std::vector<std::size_t> order(n);
        std::iota(order.begin(), order.end(), std::size_t{0});
        auto start = [&](std::size_t i) {
            const glm::vec3& a = segments[i].a;
            return std::array<float, 3>{a.x, a.y, a.z};
        };
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t x, std::size_t y) { return start(x) < start(y); });
        for (std::size_t begin = 0, end = 0; begin < n; begin = end) {
            while (end < n && start(order[end]) == start(order[begin])) ++end;
            for (std::size_t x = begin; x < end; ++x)
                for (std::size_t y = begin; y < end; ++y) {
                    const Segment& sx = segments[order[x]];
                    const Segment& sy = segments[order[y]];
                    const float lx = glm::distance(sx.a, sx.b), ly = glm::distance(sy.a, sy.b);
                    // y drops x when it runs the same way and is longer (or as long, earlier).
                    if (x == y || glm::dot(unit_direction(sx), unit_direction(sy)) < 1.0f - 1e-6f)
                        continue;
                    if (ly > lx || (ly == lx && order[y] < order[x])) drawn[order[x]] = 0;
                }
        }
    }
    auto is_shown = [&](int i) { return i >= 0 && drawn[static_cast<std::size_t>(i)] != 0; };
    // The nearest shown ancestor of each segment, and each one's shown children.
    std::vector<int> up(n, -1);
    std::vector<std::vector<int>> children(n);
    for (std::size_t i = 0; i < n; ++i) {
        int p = segments[i].parent;
        // Parents come first in a turtle's skeleton; anything else starts afresh.
        if (p >= static_cast<int>(i)) p = -1;
        while (p >= 0 && !is_shown(p)) p = up[static_cast<std::size_t>(p)];
        up[i] = p;
        if (is_shown(static_cast<int>(i)) && p >= 0)
            children[static_cast<std::size_t>(p)].push_back(static_cast<int>(i));
    }
    // next[i]: the child continuing segment i's axis, or -1.
    std::vector<int> next(n, -1);
    std::vector<char> continues(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 d = unit_direction(segments[i]);
        float best_radius = -1.0f, best_cos = -2.0f;
        for (int c : children[i]) {
            const Segment& child = segments[static_cast<std::size_t>(c)];
            const float cosine = glm::dot(d, unit_direction(child));
            if (cosine < kContinueCos) continue;
            if (std::tie(child.ra, cosine) > std::tie(best_radius, best_cos)) {
                best_radius = child.ra;
                best_cos = cosine;
                next[i] = c;
            }
        }
        if (next[i] >= 0) continues[static_cast<std::size_t>(next[i])] = 1;
    }
    // Axes in segment order of their first segment, so parents come first.
    std::vector<int> axis_of(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_shown(static_cast<int>(i)) || continues[i]) continue;
        BranchAxis branch;
        branch.parent = up[i] >= 0 ? axis_of[static_cast<std::size_t>(up[i])] : -1;
        const int index = static_cast<int>(out.axes.size());
        branch.axis.points.push_back(segments[i].a);
        branch.axis.radii.push_back(std::max(segments[i].ra, min_radius));
        int s = static_cast<int>(i);
        for (;;) {
            const Segment& seg = segments[static_cast<std::size_t>(s)];
            axis_of[static_cast<std::size_t>(s)] = index;
            const int after = next[static_cast<std::size_t>(s)];
            const float end_radius =
                after >= 0 ? std::max(seg.rb, segments[static_cast<std::size_t>(after)].ra)
                           : seg.rb;
            branch.axis.points.push_back(seg.b);
            branch.axis.radii.push_back(std::max(end_radius, min_radius));
            const float r0 = branch.axis.radii[branch.axis.radii.size() - 2];
            const float r1 = branch.axis.radii.back();
            branch.area += (r0 + r1) * glm::distance(seg.a, seg.b);
            if (after < 0) {
                branch.axis.pointed = children[static_cast<std::size_t>(s)].empty();
                break;
            }
            s = after;
        }
        out.thickest = std::max(out.thickest, branch.axis.radii.front());
        out.axes.push_back(std::move(branch));
    }
    return out;
}

PrismLook prism_look(const BranchAxes& axes, std::size_t budget) {
    PrismLook look;
    const double b = static_cast<double>(std::max<std::size_t>(budget, 1));
    // Six sides at 800 triangles, four at 200, eight at 3,000.
    look.max_sides =
        std::clamp(static_cast<int>(std::lround(6.0 * std::pow(b / 800.0, 0.25))), 3, 12);
    look.tolerance = static_cast<float>(0.004 * axes.extent * std::sqrt(800.0 / b));
    return look;
}

BranchPrisms branch_prisms(const BranchAxes& axes, std::size_t budget, std::size_t max_triangles,
                           PrismOrder order) {
    BranchPrisms out;
    const PrismLook look = prism_look(axes, budget);
    const std::size_t n = axes.axes.size();
    std::vector<std::vector<int>> children(n);
    std::vector<int> sides(n);
    // Largest area first, then the earlier axis: a max-heap of (area, -index).
    std::priority_queue<std::pair<float, int>> ready;
    for (std::size_t i = 0; i < n; ++i) {
        const int parent = axes.axes[i].parent;
        if (parent >= 0)
            children[static_cast<std::size_t>(parent)].push_back(static_cast<int>(i));
        else
            ready.emplace(axes.axes[i].area, -static_cast<int>(i));
        sides[i] = sides_for(axes.axes[i].axis.radii.front(), axes.thickest, look.max_sides,
                             look.tolerance);
    }
    auto cost_at = [&](std::size_t i, float tolerance, bool short_tip) {
        return axis_triangles(drawn_axis(axes.axes[i].axis, tolerance, short_tip), sides[i]);
    };
    // Every axis first starts at the coarsest tolerance, the largest first at the look's.
    const int first_try = order == PrismOrder::EveryAxisFirst ? kCoarserTries - 1 : 0;
    std::vector<char> drawn(n, 0);
    std::vector<float> tolerances(n, look.tolerance);
    std::vector<std::size_t> drawn_order;
    std::vector<char> short_tip(n, 0);
    std::size_t triangles = 0;
    while (!ready.empty()) {
        const auto i = static_cast<std::size_t>(-ready.top().second);
        ready.pop();
        // The look's tolerance, or coarser (twice, four times) where the branch would not
        // fit; the first branch (the trunk) is drawn however coarse it must be.
        const bool first = triangles == 0;
        float tolerance = look.tolerance * static_cast<float>(1 << first_try);
        // Every axis first: the first (the trunk, which shows most) ends in its short point
        // at once where that fits.
        if (first && order == PrismOrder::EveryAxisFirst)
            short_tip[i] = cost_at(i, tolerance, true) <= max_triangles;
        for (int tries = first_try; tries < kCoarserTries; ++tries, tolerance *= 2.0f) {
            const std::size_t cost = cost_at(i, tolerance, short_tip[i] != 0);
            if (cost == 0) break;
            if (triangles + cost > max_triangles && !(first && tries + 1 == kCoarserTries))
                continue;
            triangles += cost;
            drawn[i] = 1;
            tolerances[i] = tolerance;
            drawn_order.push_back(i);
            break;
        }
        if (!drawn[i]) continue;
        for (int child : children[i])
            ready.emplace(axes.axes[static_cast<std::size_t>(child)].area, -child);
    }
    // Every axis drawn coarse, the largest refined first: each to the finest tolerance whose
    // extra triangles fit.
    if (order == PrismOrder::EveryAxisFirst)
        for (std::size_t i : drawn_order) {
            const std::size_t now = cost_at(i, tolerances[i], short_tip[i] != 0);
            for (float finer = look.tolerance; finer < tolerances[i]; finer *= 2.0f) {
                const std::size_t cost = cost_at(i, finer, short_tip[i] != 0);
                if (triangles - now + cost > max_triangles) continue;
                triangles = triangles - now + cost;
                tolerances[i] = finer;
                break;
            }
        }
    // Short points with the triangles left, where every axis is drawn: largest axis first.
    if (drawn_order.size() == n) {
        std::vector<std::size_t> by_area(n);
        std::iota(by_area.begin(), by_area.end(), std::size_t{0});
        std::stable_sort(by_area.begin(), by_area.end(), [&](std::size_t a, std::size_t b) {
            return axes.axes[a].area > axes.axes[b].area;
        });
        for (std::size_t i : by_area) {
            if (short_tip[i]) continue;
            const std::size_t plain = cost_at(i, tolerances[i], false);
            const std::size_t tipped = cost_at(i, tolerances[i], true);
            if (tipped <= plain || triangles + (tipped - plain) > max_triangles) continue;
            triangles += tipped - plain;
            short_tip[i] = 1;
        }
    }
    // Drawn in axis order, so the mesh does not depend on the heap's order.
    for (std::size_t i = 0; i < n; ++i) {
        if (!drawn[i]) {
            ++out.left_out;
            continue;
        }
        // Each axis' polygon turned by a golden angle more than the one before: branches
        // that leave one point in mirrored directions would otherwise put corners on the same
        // spots, and a surface welded there would pass through itself.
        const float turn = kGoldenAngle * static_cast<float>(i);
        for (const TubeAxis& piece : tube_pieces(
                 drawn_axis(axes.axes[i].axis, tolerances[i], short_tip[i] != 0), sides[i])) {
            const glm::vec3 d = glm::normalize(piece.points[1] - piece.points[0]);
            const glm::vec3 a = std::abs(d.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
            const glm::vec3 u = glm::normalize(a - glm::dot(a, d) * d);
            append_tube(out.mesh, piece, sides[i],
                        std::cos(turn) * u + std::sin(turn) * glm::cross(d, u));
        }
        ++out.drawn;
    }
    return out;
}

std::size_t fewest_prism_triangles(const BranchAxes& axes, std::size_t budget) {
    const PrismLook look = prism_look(axes, budget);
    const float coarsest = look.tolerance * static_cast<float>(1 << (kCoarserTries - 1));
    std::size_t triangles = 0;
    std::size_t first = axes.axes.size();  // the largest root, drawn first
    for (std::size_t i = 0; i < axes.axes.size(); ++i) {
        const BranchAxis& branch = axes.axes[i];
        if (branch.parent < 0 && (first == axes.axes.size() || branch.area > axes.axes[first].area))
            first = i;
        triangles += axis_triangles(
            drawn_axis(branch.axis, coarsest, false),
            sides_for(branch.axis.radii.front(), axes.thickest, look.max_sides, look.tolerance));
    }
    if (first < axes.axes.size()) {  // with its short point
        const BranchAxis& trunk = axes.axes[first];
        const int sides =
            sides_for(trunk.axis.radii.front(), axes.thickest, look.max_sides, look.tolerance);
        triangles += axis_triangles(drawn_axis(trunk.axis, coarsest, true), sides) -
                     axis_triangles(drawn_axis(trunk.axis, coarsest, false), sides);
    }
    return triangles;
}

}  // namespace sylva
