// Welding by position: which vertices of a mesh sit at exactly the same point. Meshers and
// reductions may keep two vertices at one point (separate parts, seams); the quality
// measures see the surface, so they count such vertices as one.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace sylva {

struct Welding {
    // For each vertex of the mesh, its welded vertex: 0..count-1, numbered in the order of
    // each point's first vertex, so the numbering follows the mesh's.
    std::vector<std::uint32_t> vertex;
    std::size_t count = 0;
};

// Vertices weld when their positions compare equal (so 0 and -0 weld). Needs positions that
// are not NaN. Deterministic; safe to call from several threads at once.
Welding weld_by_position(const Mesh& mesh);

}  // namespace sylva
