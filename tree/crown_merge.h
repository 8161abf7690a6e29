// Low budgets and many-blob crowns. Every closed piece of a mesh keeps at least four
// triangles through any reduction, so a crown of 38 separate spheres reduced to 50
// triangles can only become 38 tetrahedra: a spray, not a crown. Bridging the nearest
// blobs with short struts until at most a few pieces remain gives shapes a small budget can
// draw, and leaves every blob's own shape as it was (growing or blending all spheres would
// swell the whole crown).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "sdf/sphere_field.h"

namespace sylva {

// Triangles a budget should leave each crown piece so it reads as a blob (an octahedron),
// not a token (a tetrahedron): a crown with more pieces than its share of the budget allows
// at this rate is merged...
inline constexpr std::size_t kTrianglesPerCrownPiece = 8;
// ... into pieces of about this many triangles each, so a piece that now spans several
// blobs still has the triangles to follow them.
inline constexpr std::size_t kTrianglesPerMergedPiece = 24;

// The number of pieces the union of the spheres forms when each radius grows by `grow`
// (spheres whose grown balls touch are one piece).
std::size_t count_crown_pieces(std::span<const Ball> balls, float grow);

// The pairs of spheres (indices into `balls`) to bridge so that the spheres and the bridges
// form at most `max_pieces` pieces: the shortest gaps first (Kruskal's order, so no bridge
// is longer than it must be). Empty when the spheres already form few enough pieces.
std::vector<std::pair<std::uint32_t, std::uint32_t>> crown_bridges(std::span<const Ball> balls,
                                                                   std::size_t max_pieces);

}  // namespace sylva
