// Leaves within a triangle budget. A scatter of thousands of leaves is more than a game tree
// can afford, so a budget keeps a subset of whole leaves that still covers the crown evenly,
// and grows each kept leaf so the crown's leaf area (how dense it reads) stays about the same.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "core/mesh.h"

namespace sylva {

// How far a kept leaf may grow: past about twice its length a leaf stops reading as a leaf.
constexpr float kMaxLeafGrowth = 2.0f;

// One leaf of a leaf mesh: its triangles (indices into the mesh's list) and its base vertex
// (its smallest vertex index: the first vertex tree/leaves.h gives it).
struct LeafPiece {
    std::vector<std::uint32_t> triangles;
    std::uint32_t base = 0;
};

// The leaves of `leaves` (tree/leaves.h: no two share a vertex), in the order of their first
// triangle.
std::vector<LeafPiece> split_leaves(const Mesh& leaves);

// A leaf's rank for thinning, a hash of where its base is: as random as the scatter, stable
// for the same leaf.
std::uint64_t leaf_rank(const glm::vec3& base);

// The number of leaves in `leaves`: its sets of triangles joined by shared vertices
// (tree/leaves.h: no two leaves share a vertex).
std::size_t count_leaves(const Mesh& leaves);

// At most `max_triangles` of the leaves' triangles, as whole leaves. Each leaf is ranked by
// a hash of its base (its first vertex): random across the crown, so the kept ones are an
// even sample, and the same leaf always gets the same rank, so a smaller budget keeps a
// subset of what a larger one keeps (LOD levels thin out, they never swap leaves). Leaves
// are kept in rank order while they fit. The kept ones are scaled about their base by
// sqrt(leaves / kept), at most `max_growth`, which keeps the total leaf area up to that cap.
// Same input, same output; the kept leaves stay in their original order.
Mesh thin_leaves(const Mesh& leaves, std::size_t max_triangles, float max_growth = kMaxLeafGrowth);

}  // namespace sylva
