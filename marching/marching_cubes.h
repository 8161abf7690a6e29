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
//
// Grid: cubic cells of size h = longest box side / resolution over the box grown by
// padding_cells * h on every side; on the shorter axes the grid is widened, symmetrically,
// by less than one cell to a whole number of cells. The field is evaluated once per grid
// node, from the calling thread. A sample is inside only when it is finite and strictly
// negative (NaN and infinities count as outside).
//
// Clipping: the outermost layer of grid nodes always counts as outside, so the mesh is
// closed even where the field is still negative at the grid border; there the surface is
// capped flat, half a cell inside the grid border. With padding_cells >= 1 this cannot
// touch a surface that lies inside `box`.
//
// Output: a closed, consistently oriented 2-manifold (possibly empty), triangles
// counter-clockwise seen from outside, one vertex per crossed grid edge plus, rarely, one
// centre vertex for a cube whose contour loops through the same face twice. Every vertex
// lies inside the grid. The same inputs give the same mesh, vertex order included.
//
// Throws std::invalid_argument when resolution < 1, padding_cells < 0, or the box is empty
// (no positive side) or not finite.
Mesh marching_cubes(const ScalarField& field, const Box& box, const MarchingCubesSettings& settings);

}  // namespace sylva
