// How the tree's fields meet the marching-cubes grid they are meshed on: how thin a branch
// may be drawn, when two primitives count as one, how far from its surface a field stays
// exact, and the cell a resolution gives a box.
//
// Constants and one pure function: no allocation, nothing thrown, safe from any thread.
// They sit in one place because the trunk's pieces, the hidden-branch test and the crown's
// bridges must sample on the same terms, or their parts would not meet.
#pragma once

#include <algorithm>
#include <glm/vec3.hpp>

#include "core/box.h"

namespace sylva {

// The thinnest a branch is drawn, in cells. Branches thinner than the grid can sample
// would break into disconnected crumbs, so radii are raised to kMinRadiusInCells cells:
// a ball that wide always holds a grid node (the cubic lattice's covering radius is
// sqrt(3)/2 = 0.87 cells), which keeps every branch in one piece. Finer twigs need a
// higher trunk_resolution.
inline constexpr float kMinRadiusInCells = 0.9f;

// Primitives closer than this to an earlier one are merged into it (cone_field.h,
// sphere_field.h).
inline constexpr float kMergeToleranceInCells = 0.125f;

// The culled fields are exact within this many cells of the surface (all marching cubes
// interpolates) and a lower bound of the distance beyond it, which is all the sparse mesher
// needs to skip empty blocks: |f(centre)| above a block's half-diagonal proves it empty.
inline constexpr float kFieldMarginInCells = 3.0f;

// The cell of `resolution` cells along `box`'s longest side.
inline float cell_size(const Box& box, int resolution) {
    glm::vec3 extent = box.max - box.min;
    return std::max({extent.x, extent.y, extent.z}) / static_cast<float>(resolution);
}

}  // namespace sylva
