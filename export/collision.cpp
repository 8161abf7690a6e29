#include "export/collision.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <numbers>

#include "core/convex_hull.h"
#include "core/disjoint_sets.h"
#include "export/part_attributes.h"

namespace sylva {

namespace {

constexpr int kRingPoints = 16;

// Points on the circle of radius r about `axis` through `center`.
void add_ring(std::vector<glm::vec3>& out, const glm::vec3& center, const glm::vec3& axis,
              float r) {
    const glm::vec3 up = glm::length(axis) > 1e-6f ? glm::normalize(axis) : glm::vec3(0, 1, 0);
    const glm::vec3 side = std::abs(up.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    const glm::vec3 u = glm::normalize(glm::cross(up, side)), v = glm::cross(up, u);
    for (int k = 0; k < kRingPoints; ++k) {
        const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / kRingPoints;
        out.push_back(center + r * (std::cos(a) * u + std::sin(a) * v));
    }
}

}  // namespace

std::vector<Mesh> collision_hulls(const Mesh& trunk, const Mesh& crown, const Skeleton& skeleton,
                                  std::size_t max_crown_hulls) {
    std::vector<Mesh> hulls;
    if (!trunk.positions.empty() && !skeleton.segments.empty()) {
        float ground = std::numeric_limits<float>::max(),
              top = std::numeric_limits<float>::lowest();
        for (const Mesh* part : {&trunk, &crown})
            for (const glm::vec3& p : part->positions) {
                ground = std::min(ground, p.y);
                top = std::max(top, p.y);
            }
        // The trunk: the segments of the lowest depth (0, or 1 on a bush of many stems).
        int trunk_depth = std::numeric_limits<int>::max();
        for (const Segment& s : skeleton.segments) trunk_depth = std::min(trunk_depth, s.depth);
        float first_branch = top;
        for (const Segment& s : skeleton.segments)
            if (s.depth > trunk_depth) first_branch = std::min(first_branch, s.a.y);
        const float cut = std::max(first_branch, ground + 0.25f * (top - ground));
        // The trunk's segments below the cut as rings of their own radius, clipped at the
        // cut, the lowest one reaching down to the ground: a reduced trunk may have no vertex
        // between its foot and the first fork, so its vertices alone can make a flat disc.
        std::vector<glm::vec3> stem;
        const Segment* lowest = nullptr;
        for (const Segment& s : skeleton.segments) {
            if (s.depth != trunk_depth || std::min(s.a.y, s.b.y) > cut) continue;
            glm::vec3 a = s.a, b = s.b;
            float ra = s.ra, rb = s.rb;
            if (a.y > b.y) {
                std::swap(a, b);
                std::swap(ra, rb);
            }
            if (b.y > cut) {
                const float t = (cut - a.y) / (b.y - a.y);
                b = a + t * (b - a);
                rb = ra + t * (rb - ra);
            }
            add_ring(stem, a, s.b - s.a, ra);
            add_ring(stem, b, s.b - s.a, rb);
            if (!lowest || std::min(s.a.y, s.b.y) < std::min(lowest->a.y, lowest->b.y)) lowest = &s;
        }
        if (lowest) {
            const bool a_low = lowest->a.y <= lowest->b.y;
            const glm::vec3 foot = a_low ? lowest->a : lowest->b;
            add_ring(stem, {foot.x, ground, foot.z}, glm::vec3(0, 1, 0),
                     a_low ? lowest->ra : lowest->rb);
        }
        const std::vector<int> owner = owning_segments(trunk, skeleton);
        for (std::size_t v = 0; v < trunk.positions.size(); ++v)
            if (owner[v] >= 0 &&
                skeleton.segments[static_cast<std::size_t>(owner[v])].depth == trunk_depth &&
                trunk.positions[v].y <= cut)
                stem.push_back(trunk.positions[v]);
        if (Mesh hull = extreme_point_hull(stem); !hull.triangles.empty())
            hulls.push_back(std::move(hull));
    }
    if (crown.positions.empty() || max_crown_hulls == 0) return hulls;
    DisjointSets sets(crown.positions.size());
    for (const auto& t : crown.triangles) {
        sets.unite(t[0], t[1]);
        sets.unite(t[0], t[2]);
    }
    // Pieces in order of their first vertex, then the largest first (stable: ties keep it).
    std::map<std::uint32_t, std::size_t> piece_of_root;
    std::vector<std::vector<glm::vec3>> pieces;
    for (std::uint32_t v = 0; v < crown.positions.size(); ++v) {
        auto [it, added] = piece_of_root.try_emplace(sets.find(v), pieces.size());
        if (added) pieces.emplace_back();
        pieces[it->second].push_back(crown.positions[v]);
    }
    std::stable_sort(pieces.begin(), pieces.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    std::size_t crown_hulls = 0;
    for (const auto& piece : pieces) {
        if (crown_hulls == max_crown_hulls) break;
        if (Mesh hull = extreme_point_hull(piece); !hull.triangles.empty()) {
            hulls.push_back(std::move(hull));
            ++crown_hulls;
        }
    }
    return hulls;
}

}  // namespace sylva
