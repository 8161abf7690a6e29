// How much a convex hull of crown points fills that the points do not: the sky a hull over a
// gap (between two tiers of an umbrella, between the blobs of a spray) shows as foliage. Used
// to choose between clusterings of a crown into hulls (tree/crown_hulls.h).
#pragma once

#include <glm/vec3.hpp>
#include <span>

namespace sylva {

// Over five views (four from the side, 45 degrees apart, and one from above; orthographic),
// the area of the points' projected 2D convex hull less the area of the grid cells of side
// `cell` the projected points fall in, each view at least 0, summed, in square metres. Points
// that cover their outline (a solid lump sampled more densely than `cell`) give about 0;
// two lumps apart give about the gap between them. Fewer than 3 points give 0. Pure, and
// linear-logarithmic in the points.
double hull_gap(std::span<const glm::vec3> points, float cell);

}  // namespace sylva
