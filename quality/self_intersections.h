// Triangles of one piece that cut through each other: a game mesh whose reduction folded a
// face through the surface shows it as a crease or a hole, which a player sees. Pieces that
// overlap each other (a branch stuck into the trunk, a crown blob into another) are how
// trees are built and are not counted.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace sylva {

struct SelfIntersections {
    // Triangles of one piece that intersect beyond what they share (a common edge or
    // vertex): pairs of indices into the mesh's triangles, the smaller first, sorted.
    std::vector<std::array<std::uint32_t, 2>> pairs;
    // Triangles with collinear corners, left out of the test (they bound no area).
    std::vector<std::uint32_t> degenerate;
    // For each triangle its piece, 0..pieces-1, numbered in the order of each piece's
    // first triangle.
    std::vector<std::uint32_t> piece;
    std::vector<std::size_t> pairs_per_piece;
    std::size_t pieces = 0;
    // Pieces that are no 2-manifold once welded (an edge of three faces, two sheets
    // touching at a vertex), tested as a triangle soup with the same predicates.
    std::size_t soup_pieces = 0;
};

// Vertices at the same position are welded first (quality/weld.h); a piece is a set of
// triangles connected through shared vertices. Each piece is tested alone with
// CGAL::Polygon_mesh_processing::self_intersections (exact predicates, so a pair is found
// however thin the overlap): two triangles intersect when they meet anywhere but in what they
// share; triangles sharing an edge intersect only when they lie in one plane and overlap,
// and duplicate triangles always do. Needs positions that are not NaN; open meshes are fine.
// Deterministic; safe to call from several threads at once. Costs about O(n log n) for n
// triangles (box intersection, then an exact test per pair of overlapping boxes).
SelfIntersections find_self_intersections(const Mesh& mesh);

// find_self_intersections(mesh).pairs.size(): 0 for a mesh whose pieces are each free of
// self-intersections.
std::size_t self_intersecting_pairs(const Mesh& mesh);

}  // namespace sylva
