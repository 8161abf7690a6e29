// Topology simplification for budgets that handles would not allow. Where branches cross,
// the union of their cones closes a loop: the surface gets a handle (genus), and no edge
// collapse that keeps the manifold can remove it, so every handle pins some dozen
// triangles (the willow's 200 handles alone need 2,600). Cutting a handle along its
// shortest non-separating loop (usually around the thinner branch, next to the crossing)
// and capping both sides removes it with a change of shape the size of that branch's
// cross-section, invisible at game scale. The result stays a closed, consistently
// oriented 2-manifold.
#pragma once

#include <cstddef>

#include "core/cancel.h"
#include "core/mesh.h"

namespace sylva {

// Sum over the connected components of their genus (from V - E + F); the mesh must be a
// closed 2-manifold.
std::size_t genus(const Mesh& mesh);

// Cuts up to `max_cuts` handles, short loops first. Each round finds candidate loops
// through many roots at once (Erickson and Whittlesey's greedy system of loops, grown from a
// forest of shortest paths: a cell per root, and per cell its shortest non-separating loop
// through the root), takes the shortest ones that stay apart, keeps uncut those that would
// separate the surface together with the others, and cuts the rest: each cut duplicates the
// loop's vertices and closes both sides with a fan around the loop's centroid. A round whose
// cuts do not lower the genus by their number or break the manifold (check_topology,
// restricted to the cuts) is redone one cut at a time, each checked alone. Returns the number
// of handles cut.
// Precondition: a closed 2-manifold. Deterministic. Throws Cancelled once `cancel` is set
// (polled per round; the mesh is then left with the cuts of the finished rounds).
std::size_t cut_handles(Mesh& mesh, std::size_t max_cuts, CancelFlag cancel = nullptr);

}  // namespace sylva
