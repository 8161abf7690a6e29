#include "infer/skeleton_figures.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <unordered_map>

#include "core/random.h"

namespace sylva {

SkeletonFigures skeleton_figures(const Skeleton& skeleton) {
    SkeletonFigures f;
    f.segments = skeleton.segments.size();
    if (skeleton.segments.empty()) return f;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const Segment& s : skeleton.segments) {
        f.total_length += glm::length(s.b - s.a);
        lo = glm::min(lo, glm::min(s.a, s.b));
        hi = glm::max(hi, glm::max(s.a, s.b));
        const std::size_t d = static_cast<std::size_t>(std::max(s.depth, 0));
        if (f.per_depth.size() <= d) f.per_depth.resize(d + 1, 0);
        ++f.per_depth[d];
    }
    f.height = hi.y - lo.y;
    f.crown_width = std::max(hi.x - lo.x, hi.z - lo.z);
    return f;
}

std::vector<glm::vec3> sample_skeleton(const Skeleton& skeleton, float spacing) {
    std::vector<glm::vec3> points;
    for (const Segment& s : skeleton.segments) {
        const float length = glm::length(s.b - s.a);
        const int pieces = std::clamp(static_cast<int>(std::ceil(length / spacing)), 1, 200);
        for (int k = 0; k <= pieces; ++k)
            points.push_back(s.a + (s.b - s.a) * (static_cast<float>(k) / pieces));
    }
    return points;
}

namespace {

struct Grid {
    struct Cell {
        glm::ivec3 at;
        std::vector<glm::vec3> points;
    };
    float cell;
    std::vector<Cell> list;
    std::unordered_map<std::uint64_t, std::size_t> index;  // key -> position in list
    static std::uint64_t key(int x, int y, int z) {
        return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x) & 0x1FFFFF) << 42) |
               (static_cast<std::uint64_t>(static_cast<std::uint32_t>(y) & 0x1FFFFF) << 21) |
               (static_cast<std::uint64_t>(static_cast<std::uint32_t>(z) & 0x1FFFFF));
    }
    glm::ivec3 at(const glm::vec3& p) const { return glm::ivec3(glm::floor(p / cell)); }
    Grid(const std::vector<glm::vec3>& points, float c) : cell(c) {
        for (const glm::vec3& p : points) {
            const glm::ivec3 i = at(p);
            const auto [it, added] = index.try_emplace(key(i.x, i.y, i.z), list.size());
            if (added) list.push_back({i, {}});
            list[it->second].points.push_back(p);
        }
    }
    void visit(const Cell& c, const glm::vec3& p, double& best) const {
        for (const glm::vec3& q : c.points)
            best = std::min(best, static_cast<double>(glm::length(p - q)));
    }
    // Distance to the nearest point, or some distance no larger than `enough` once one is
    // found that close (a point nearer than the largest distance so far cannot raise a
    // maximum). Searches shells of cells outwards, then, for a point far from every cell,
    // every cell whose box is nearer than the best so far: a far point costs one pass over
    // the cells, not a cube of empty ones.
    double nearest(const glm::vec3& p, double enough) const {
        const glm::ivec3 c = at(p);
        double best = std::numeric_limits<double>::infinity();
        constexpr int kShells = 4;
        for (int r = 0; r <= kShells; ++r) {
            if (best < (r - 1) * static_cast<double>(cell) || best <= enough) return best;
            for (int x = -r; x <= r; ++x)
                for (int y = -r; y <= r; ++y)
                    for (int z = -r; z <= r; ++z) {
                        if (std::max({std::abs(x), std::abs(y), std::abs(z)}) != r) continue;
                        auto it = index.find(key(c.x + x, c.y + y, c.z + z));
                        if (it != index.end()) visit(list[it->second], p, best);
                    }
        }
        if (best < kShells * static_cast<double>(cell) || best <= enough) return best;
        for (const Cell& other : list) {
            const glm::vec3 lo = glm::vec3(other.at) * cell;
            const glm::vec3 gap = glm::max(glm::max(lo - p, p - (lo + cell)), glm::vec3(0.0f));
            if (static_cast<double>(glm::length(gap)) >= best) continue;
            visit(other, p, best);
            if (best <= enough) return best;
        }
        return best;
    }
};

double directed(const std::vector<glm::vec3>& from, const Grid& to) {
    double worst = 0.0;
    for (const glm::vec3& p : from) worst = std::max(worst, to.nearest(p, worst));
    return worst;
}

}  // namespace

double hausdorff_distance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
    glm::vec3 lo = a[0], hi = a[0];
    for (const auto* set : {&a, &b})
        for (const glm::vec3& p : *set) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    const float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-6f});
    const float cell = extent / 64.0f;
    const Grid ga(a, cell), gb(b, cell);
    return std::max(directed(a, gb), directed(b, ga));
}

double skeleton_hausdorff(const Skeleton& a, const Skeleton& b) {
    const float spacing = static_cast<float>(
        std::max({skeleton_figures(a).height, skeleton_figures(b).height, 1e-3}) / 200.0);
    return hausdorff_distance(sample_skeleton(a, spacing), sample_skeleton(b, spacing));
}

Skeleton jittered(Skeleton s, std::uint64_t seed) {
    Random random(seed);
    std::vector<glm::vec3> offset(s.segments.size());
    for (std::size_t i = 0; i < s.segments.size(); ++i) {
        const float length = glm::length(s.segments[i].b - s.segments[i].a);
        glm::vec3 d(random.uniform() - 0.5, random.uniform() - 0.5, random.uniform() - 0.5);
        offset[i] = d * (0.06f * length);
    }
    for (std::size_t i = 0; i < s.segments.size(); ++i) s.segments[i].b += offset[i];
    for (Segment& seg : s.segments)
        if (seg.parent >= 0) seg.a = s.segments[static_cast<std::size_t>(seg.parent)].b;
    return s;
}

}  // namespace sylva
