// Convex hulls for collision shapes (export/collision.h) and low-budget crowns
// (tree/crown_hulls.h): small ones, of a point set's extremes along a fixed
// set of directions, so a hull has at most 2 * kHullDirections - 4 triangles whatever the
// input (Unity's convex MeshCollider takes at most 255). Written here because none of the
// project's libraries (GLM, OpenVDB, meshoptimizer, ...) computes a 3D hull.
#pragma once

#include <span>

#include "core/mesh.h"

namespace sylva {

constexpr int kHullDirections = 64;

// The convex hull of `points`' extreme points along kHullDirections directions spread over
// the sphere (it lies inside the true hull, touching it at those points): a closed mesh,
// counter-clockwise seen from outside. Empty when the points span no volume (fewer than
// four, or all on a plane). Same input, same output.
Mesh extreme_point_hull(std::span<const glm::vec3> points);

// The convex hull of all `points` (incremental; fine for a few hundred): one closed sphere,
// every edge shared by two triangles. Empty as above, and (not seen) when no rounding margin
// up to 1e-3 of the points' extent gives one.
Mesh convex_hull(std::span<const glm::vec3> points);

}  // namespace sylva
