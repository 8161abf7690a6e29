// Low budgets and many-blob crowns. Every closed piece of a mesh keeps at least four
// triangles through any reduction, so a crown of 38 separate spheres reduced to 50
// triangles can only become 38 tetrahedra: a spray, not a crown. Growing every sphere by
// one common radius until at most a few pieces remain merges neighbours into shapes a small
// budget can draw (seed 001's crown fusion, pushed further where the budget asks for it).
#pragma once

#include <cstddef>
#include <span>

#include "sdf/sphere_field.h"

namespace sylva {

// Triangles a budget should leave each crown piece so it reads as a blob (an octahedron),
// not a token (a tetrahedron).
inline constexpr std::size_t kTrianglesPerCrownPiece = 8;

// The number of pieces the union of the spheres forms when each radius grows by `grow`
// (spheres whose grown balls touch are one piece).
std::size_t count_crown_pieces(std::span<const Ball> balls, float grow);

// The smallest common growth (to 1% of the crown's size) after which the spheres form at
// most `max_pieces` pieces; 0 when they already do.
float crown_merge_radius(std::span<const Ball> balls, std::size_t max_pieces);

}  // namespace sylva
