// A sparse crown: blobs far apart for their size (a spruce's tufts at the tips of bare
// whorl branches). Bridging such blobs into a few pieces, or wrapping them in hulls, lays
// slabs over the gaps that the full-detail tree shows open, and a reduction of many tiny
// blobs at once gives some a tetrahedron and others more; drawn instead as one small regular
// polyhedron each (a tetrahedron, a triangular bipyramid or an octahedron, as many triangles
// as the budget gives every blob), sized to the blob's mean outline, each blob keeps its
// place and reads as a tuft, and where the budget cannot draw every blob the smallest go.
//
// Pure functions on plain data; no state, safe from any thread on distinct meshes. Throw
// nothing of their own (std::bad_alloc aside).
#pragma once

#include <cstddef>

#include "core/mesh.h"

namespace sylva {

// Blobs lie on average farther apart than this many times the larger one's radius (centre to
// centre, each from its nearest other) in a sparse crown: the slenderness at which a
// bridge between two of them is a rod, not a neck (tree/crown_bridges.h).
inline constexpr double kSparseCrownSpacing = 4.0;

// The number of connected pieces of a meshed crown if it is sparse, else 0. Sparse: at least
// two pieces, and the mean over them of the distance to the nearest other piece's centre over
// the larger of the two radii is above kSparseCrownSpacing (a piece's centre is its vertices'
// mean, its radius their mean distance from it).
std::size_t sparse_crown_pieces(const Mesh& crown);

// The crown's pieces as regular polyhedra within `budget` triangles: octahedra, bipyramids
// or tetrahedra (8, 6 or 4 triangles, as many as the budget gives every piece; under four a
// piece the largest pieces that fit are kept, the rest dropped), each about its piece's
// centre with the surface area of the ball of the piece's radius (so by Cauchy's formula,
// Santaló 1976, the ball's mean outline), turned by a golden angle from the one before.
// Empty for an empty crown or a budget under four. Closed, 2-manifold, outward pieces, each
// free of self-intersection.
Mesh sparse_crown_polyhedra(const Mesh& crown, std::size_t budget);

}  // namespace sylva
