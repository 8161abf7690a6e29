// The sizes every reader and writer of the layout module agrees on, so that whatever one
// stage accepts or makes, the next accepts too: an example the mesh readers take derives a
// grammar the grammar reader takes back, and every label number fits in 64 bits.
#pragma once

#include <cstdint>

namespace sylva::layout {

// An example (polygon_mesh.h): vertices and polygons.
inline constexpr int kMaxExampleVertices = 200000;
inline constexpr int kMaxExamplePolygons = 20000;
// Distinct edge directions: each undirected edge brings at most two, and a planar example
// has fewer than 3 x its vertices edges.
inline constexpr int kMaxDirections = 6 * kMaxExampleVertices;
// Colours: the outside plus one per polygon at most.
inline constexpr int kMaxColors = kMaxExamplePolygons + 1;
// A graph of a grammar (a starter may be the whole example).
inline constexpr int kMaxGraphVertices = kMaxExampleVertices;
// (dir x colours + left) x colours + right < kMaxDirections x kMaxColors^2 < 2^63.
static_assert(static_cast<double>(kMaxDirections) * kMaxColors * kMaxColors < 9.2e18);

}  // namespace sylva::layout
