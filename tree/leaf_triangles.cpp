#include "tree/leaf_triangles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numeric>
#include <vector>

#include "tree/leaf_thinning.h"

namespace sylva {
namespace {

// A leaf whose outline has more corners than this loses too much of it in one triangle.
constexpr std::size_t kMostCorners = 4;
// Leaves whose median length is at least this share of the foliage's extent are seen one by
// one (a palm's leaflets); smaller ones read as foliage, which cards draw well.
constexpr float kLargeLeaf = 0.1f;

glm::vec3 doubled_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return glm::cross(b - a, c - a);
}

// A leaf's distinct vertices, in index order (its base first, tree/leaves.h).
std::vector<std::uint32_t> corners_of(const Mesh& leaves, const LeafPiece& leaf) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t f : leaf.triangles)
        out.insert(out.end(), leaves.triangles[f].begin(), leaves.triangles[f].end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace

bool leaves_fit_as_triangles(const Mesh& leaves, std::size_t max_triangles) {
    if (leaves.triangles.size() <= max_triangles || max_triangles == 0) return false;
    const std::vector<LeafPiece> pieces = split_leaves(leaves);
    if (static_cast<double>(pieces.size()) >
        kLeavesPerTriangle * static_cast<double>(max_triangles))
        return false;
    std::vector<float> lengths;
    for (const LeafPiece& leaf : pieces) {
        const std::vector<std::uint32_t> corners = corners_of(leaves, leaf);
        if (corners.size() > kMostCorners) return false;
        float length = 0.0f;
        for (std::uint32_t v : corners)
            length =
                std::max(length, glm::distance(leaves.positions[v], leaves.positions[leaf.base]));
        lengths.push_back(length);
    }
    glm::vec3 low = leaves.positions.front(), high = low;
    for (const glm::vec3& p : leaves.positions) low = glm::min(low, p), high = glm::max(high, p);
    const glm::vec3 size = high - low;
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    return lengths[lengths.size() / 2] >= kLargeLeaf * std::max({size.x, size.y, size.z});
}

Mesh leaf_triangles(const Mesh& leaves, std::size_t max_triangles) {
    Mesh out;
    if (leaves.triangles.empty() || max_triangles == 0) return out;
    const std::vector<LeafPiece> pieces = split_leaves(leaves);
    // Kept: the first max_triangles leaves in thin_leaves()' rank order.
    std::vector<std::uint64_t> rank(pieces.size());
    for (std::size_t l = 0; l < pieces.size(); ++l)
        rank[l] = leaf_rank(leaves.positions[pieces[l].base]);
    std::vector<std::size_t> by_rank(pieces.size());
    std::iota(by_rank.begin(), by_rank.end(), std::size_t{0});
    std::stable_sort(by_rank.begin(), by_rank.end(),
                     [&](std::size_t a, std::size_t b) { return rank[a] < rank[b]; });
    const std::size_t kept = std::min(pieces.size(), max_triangles);
    std::vector<char> keep(pieces.size(), 0);
    for (std::size_t i = 0; i < kept; ++i) keep[by_rank[i]] = 1;
    // What a triangle each leaves of the budget keeps leaves whole, in rank order while
    // they fit: a budget near the leaves' own triangles draws most of them as they are.
    std::vector<char> whole(pieces.size(), 0);
    std::size_t spare = max_triangles - kept;
    for (std::size_t i = 0; i < kept && spare > 0; ++i) {
        const std::size_t more = pieces[by_rank[i]].triangles.size() - 1;
        if (more > spare) continue;
        whole[by_rank[i]] = 1;
        spare -= more;
    }
    // Each kept leaf stands for its share of the leaves left out.
    const float growth = static_cast<float>(pieces.size()) / static_cast<float>(kept);

    for (std::size_t l = 0; l < pieces.size(); ++l) {
        if (!keep[l]) continue;
        const LeafPiece& leaf = pieces[l];
        if (whole[l]) {
            const std::vector<std::uint32_t> corners = corners_of(leaves, leaf);
            const auto at = static_cast<std::uint32_t>(out.positions.size());
            for (std::uint32_t v : corners) out.positions.push_back(leaves.positions[v]);
            for (std::uint32_t f : leaf.triangles) {
                std::array<std::uint32_t, 3> t = leaves.triangles[f];
                for (std::uint32_t& v : t)
                    v = at +
                        static_cast<std::uint32_t>(
                            std::lower_bound(corners.begin(), corners.end(), v) - corners.begin());
                out.triangles.push_back(t);
            }
            continue;
        }
        // The leaf's area and centroid, and the normal it faces.
        float area = 0.0f;
        glm::vec3 centroid(0.0f), facing(0.0f);
        for (std::uint32_t f : leaf.triangles) {
            const auto& t = leaves.triangles[f];
            const glm::vec3 &a = leaves.positions[t[0]], &b = leaves.positions[t[1]],
                            &c = leaves.positions[t[2]];
            const glm::vec3 n = doubled_normal(a, b, c);
            const float part = 0.5f * glm::length(n);
            area += part;
            centroid += part * (a + b + c) / 3.0f;
            if (glm::length(facing) == 0.0f) facing = n;
        }
        if (!(area > 0.0f)) continue;
        centroid /= area;
        // Its largest triangle of its own corners.
        const std::vector<std::uint32_t> corners = corners_of(leaves, leaf);
        float largest = 0.0f;
        std::array<std::uint32_t, 3> best{};
        for (std::size_t i = 0; i < corners.size(); ++i)
            for (std::size_t j = i + 1; j < corners.size(); ++j)
                for (std::size_t k = j + 1; k < corners.size(); ++k) {
                    const float a = glm::length(doubled_normal(leaves.positions[corners[i]],
                                                               leaves.positions[corners[j]],
                                                               leaves.positions[corners[k]]));
                    if (a > largest) {
                        largest = a;
                        best = {corners[i], corners[j], corners[k]};
                    }
                }
        if (!(largest > 0.0f)) continue;
        largest *= 0.5f;
        // Moved to the leaf's centroid and scaled to its (grown) area.
        const glm::vec3 middle =
            (leaves.positions[best[0]] + leaves.positions[best[1]] + leaves.positions[best[2]]) /
            3.0f;
        const float scale = std::sqrt(growth * area / largest);
        // The corner nearest the leaf's base first (corners are in index order, base first:
        // best[0] is the base when the triangle has it), facing as the leaf does.
        std::array<glm::vec3, 3> p;
        for (int k = 0; k < 3; ++k)
            p[static_cast<std::size_t>(k)] =
                centroid + scale * (leaves.positions[best[static_cast<std::size_t>(k)]] - middle);
        const glm::vec3 base = leaves.positions[leaf.base];
        std::size_t first = 0;
        for (std::size_t k = 1; k < 3; ++k)
            if (glm::distance(p[k], base) < glm::distance(p[first], base)) first = k;
        std::rotate(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(first), p.end());
        if (glm::dot(doubled_normal(p[0], p[1], p[2]), facing) < 0.0f) std::swap(p[1], p[2]);
        const auto at = static_cast<std::uint32_t>(out.positions.size());
        out.positions.insert(out.positions.end(), p.begin(), p.end());
        out.triangles.push_back({at, at + 1, at + 2});
    }
    return out;
}

}  // namespace sylva
