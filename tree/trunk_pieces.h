// The trunk as signed-distance fields of capped cones (Heuer 2022): one field over the
// segments (trunk_field), or, for a game mesh, several fields over whole subtrees of the
// skeleton (trunk_pieces) that the reduction can share out to both cores.
//
// Needs segments whose parents come before them for the pieces (else one piece); widens
// branches thinner than the grid draws (field_grid.h). Throws Cancelled once `cancel` is
// set, from building a field's bins. Pure functions of their arguments, safe to call from
// any thread; trunk_pieces builds its fields on oneTBB's pool. Partitioning lives apart from
// the pipeline because its shares are tuned to the reduction's lanes (lowpoly/decimate.h),
// not to the wiring.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/cancel.h"
#include "core/skeleton.h"
#include "sdf/cone_field.h"

namespace sylva {

// The trunk's field over `segments` meshed with cells of `cell`; empty when no segment has a
// width.
std::optional<ConeField> trunk_field(std::span<const Segment> segments, float cell,
                                     float joint_blend, CancelFlag cancel);

// A game mesh's trunk, meshed as several solids that overlap where they meet: each is
// whole subtrees of the skeleton (a branch with all it carries), an eighth, an eighth, a
// quarter and the rest (with the root) of the surface, so that the reduction can deal them
// to both cores in any share of eighths (lowpoly/decimate.h: half the tree's triangles
// each, with the crown on one of them), and branches of different solids that cross make no
// handle. The surface is the hard union's either way; only where two solids meet, a
// branch's base lies inside its parent. Returns the fields of the groups that hold a segment
// with a width, built beside each other, among the segments `shown` (1 where the trunk draws
// it); one piece when the trunk is too small to split (the reduction would not split it),
// has a joint blend, or lists a child before its parent.
std::vector<ConeField> trunk_pieces(const Skeleton& skeleton, std::span<const std::uint8_t> shown,
                                    float cell, float joint_blend, CancelFlag cancel);

}  // namespace sylva
