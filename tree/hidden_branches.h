// The hidden-branch test: which branches of a game mesh's trunk the crown hides, so that the
// trunk's field leaves them out (drop_hidden). A hidden branch costs triangles no one sees,
// and where hidden twigs cross they make the handles that cost a reduction most of its time.
//
// Needs the crown's field (any SphereField; the test reads its sign and depth, so a
// distance bound gives the exact answer) and the trunk's cell. Throws nothing of its own.
// Reads its arguments only and tests the segments on oneTBB's pool; safe to call from any
// thread while nothing writes the skeleton or the crown.
#pragma once

#include <cstdint>
#include <vector>

#include "core/skeleton.h"
#include "sdf/sphere_field.h"

namespace sylva {

// 1 for each segment of `skeleton` the trunk must draw, 0 for one the crown hides. A branch
// is hidden when every point of its axis (sampled at most half a radius apart) lies at least
// its radius inside the crown; a twig thinner than half a `cell` (drawn a cell wide) when
// its axis lies inside the crown.
std::vector<std::uint8_t> visible_segments(const Skeleton& skeleton, const SphereField& crown,
                                           float cell);

}  // namespace sylva
