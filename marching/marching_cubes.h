// Marching cubes: turns any signed distance field into a closed triangle mesh.
//
// The field is negative inside. The surface is watertight by construction: each cube face
// decides its own contour from its four samples alone (asymptotic decider, evaluated in a
// canonical corner order), so the two cubes sharing a face always agree; vertices are
// welded by global edge id; a sample counts as inside only when strictly negative.
#pragma once

#include "marching/mesh.h"

#include <functional>

namespace sylva {

using ScalarField = std::function<float(const glm::vec3&)>;

struct MarchingCubesSettings {
    // Cells along the longest side of the box (seed 001: P_Tres / P_Cres, 10-200).
    int resolution = 64;
    // Extra empty cells added on every side so the surface is never clipped by the box.
    int padding_cells = 2;
};

// Meshes the zero level set of `field` inside `box` (grown by the padding).
// Throws std::invalid_argument when resolution < 1 or the box is empty or not finite.
Mesh marching_cubes(const ScalarField& field, const Box& box, const MarchingCubesSettings& settings);

}  // namespace sylva
