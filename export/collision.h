// Collision shapes for game engines: a convex hull around the bottom of the trunk (from
// the ground up to the first branch, at least a quarter of the tree's height, as wide as
// the trunk's segments there) and one around each of the
// largest crown pieces. Hulls, not the render mesh: engines collide fastest with few
// convex pieces, and Unreal's UCX_ / Godot's -convcolonly want convex ones.
#pragma once

#include <vector>

#include "core/mesh.h"
#include "core/skeleton.h"

namespace sylva {

constexpr std::size_t kMaxCrownHulls = 8;

// The trunk's hull first (when the trunk has one), then the crown pieces' by size (vertex
// count), at most `max_crown_hulls` of them. Each is closed and convex (convex_hull.h).
std::vector<Mesh> collision_hulls(const Mesh& trunk, const Mesh& crown, const Skeleton& skeleton,
                                  std::size_t max_crown_hulls = kMaxCrownHulls);

}  // namespace sylva
