#include "tree/leaf_thinning.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "core/random.h"

namespace sylva {
namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

}  // namespace

std::uint64_t leaf_rank(const glm::vec3& base) {
    std::uint64_t seed = 0;
    for (float c : {base.x, base.y, base.z})
        seed = Random(seed ^ std::bit_cast<std::uint32_t>(c)).next();
    return seed;
}

std::vector<LeafPiece> split_leaves(const Mesh& mesh) {
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (const auto& t : mesh.triangles)
        for (int k = 1; k < 3; ++k) {
            // The smaller index becomes the root, so a leaf's root is its first vertex.
            const std::uint32_t a = find_root(parent, t[0]), b = find_root(parent, t[k]);
            parent[std::max(a, b)] = std::min(a, b);
        }
    std::vector<LeafPiece> leaves;
    std::vector<std::int64_t> leaf_of_root(mesh.positions.size(), -1);
    for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
        const std::uint32_t root = find_root(parent, mesh.triangles[f][0]);
        if (leaf_of_root[root] < 0) {
            leaf_of_root[root] = static_cast<std::int64_t>(leaves.size());
            leaves.push_back({{}, root});
        }
        leaves[static_cast<std::size_t>(leaf_of_root[root])].triangles.push_back(f);
    }
    return leaves;
}

std::size_t count_leaves(const Mesh& leaves) {
    return split_leaves(leaves).size();
}

Mesh thin_leaves(const Mesh& leaves, std::size_t max_triangles, float max_growth) {
    if (leaves.triangles.size() <= max_triangles) return leaves;
    const std::vector<LeafPiece> all = split_leaves(leaves);
    std::vector<std::uint64_t> rank(all.size());
    for (std::size_t l = 0; l < all.size(); ++l) rank[l] = leaf_rank(leaves.positions[all[l].base]);

    std::vector<std::size_t> by_rank(all.size());
    std::iota(by_rank.begin(), by_rank.end(), std::size_t{0});
    std::stable_sort(by_rank.begin(), by_rank.end(),
                     [&](std::size_t a, std::size_t b) { return rank[a] < rank[b]; });
    // A prefix of the rank order, so smaller budgets keep subsets of larger ones.
    std::vector<bool> keep(all.size(), false);
    std::size_t triangles = 0, kept = 0;
    for (std::size_t i : by_rank) {
        if (triangles + all[i].triangles.size() > max_triangles) break;
        triangles += all[i].triangles.size();
        keep[i] = true;
        ++kept;
    }

    Mesh out;
    if (kept == 0) return out;
    const float growth =
        std::min(max_growth, static_cast<float>(std::sqrt(double(all.size()) / double(kept))));
    std::vector<std::uint32_t> new_index(leaves.positions.size());
    for (std::size_t l = 0; l < all.size(); ++l) {
        if (!keep[l]) continue;
        // The leaf's vertices in their original order, so its base stays its first vertex.
        std::vector<std::uint32_t> vertices;
        for (std::uint32_t f : all[l].triangles)
            vertices.insert(vertices.end(), leaves.triangles[f].begin(), leaves.triangles[f].end());
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
        const glm::vec3 base = leaves.positions[all[l].base];
        for (std::uint32_t v : vertices) {
            new_index[v] = static_cast<std::uint32_t>(out.positions.size());
            out.positions.push_back(base + (leaves.positions[v] - base) * growth);
        }
        for (std::uint32_t f : all[l].triangles) {
            const auto& t = leaves.triangles[f];
            out.triangles.push_back({new_index[t[0]], new_index[t[1]], new_index[t[2]]});
        }
    }
    return out;
}

}  // namespace sylva
