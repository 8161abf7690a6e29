#include "export/collision.h"

#include <algorithm>
#include <limits>
#include <map>

#include "core/convex_hull.h"
#include "core/disjoint_sets.h"
#include "export/part_attributes.h"

namespace sylva {

std::vector<Mesh> collision_hulls(const Mesh& trunk, const Mesh& crown, const Skeleton& skeleton,
                                  std::size_t max_crown_hulls) {
    std::vector<Mesh> hulls;
    if (!trunk.positions.empty() && !skeleton.segments.empty()) {
        float ground = std::numeric_limits<float>::max(),
              top = std::numeric_limits<float>::lowest();
        for (const glm::vec3& p : trunk.positions) {
            ground = std::min(ground, p.y);
            top = std::max(top, p.y);
        }
        float first_branch = top;
        for (const Segment& s : skeleton.segments)
            if (s.depth > 0) first_branch = std::min(first_branch, s.a.y);
        const float cut = std::max(first_branch, ground + 0.25f * (top - ground));
        const std::vector<int> owner = owning_segments(trunk, skeleton);
        std::vector<glm::vec3> stem;
        for (std::size_t v = 0; v < trunk.positions.size(); ++v)
            if (owner[v] >= 0 && skeleton.segments[static_cast<std::size_t>(owner[v])].depth == 0 &&
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
