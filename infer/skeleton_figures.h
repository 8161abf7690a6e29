// The figures by which two skeletons are compared (the fit report of `sylva infer`, its
// tests and benchmark): segment count, total branch length, height, crown width, segments
// per branch depth, and the symmetric Hausdorff distance between points sampled along both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/skeleton.h"

namespace sylva {

struct SkeletonFigures {
    std::size_t segments = 0;
    double total_length = 0.0;           // meters, all segments
    double height = 0.0;                 // highest point over the lowest, meters
    double crown_width = 0.0;            // the larger horizontal extent (x or z), meters
    std::vector<std::size_t> per_depth;  // segments at branch depth 0, 1, ...
};

SkeletonFigures skeleton_figures(const Skeleton& skeleton);

// Points along every segment at most `spacing` apart (at most 200 pieces a segment: a
// segment longer than 200 spacings, far longer than the tree is tall, is no real branch but
// would cost its square in distance queries), both ends included.
std::vector<glm::vec3> sample_skeleton(const Skeleton& skeleton, float spacing);

// The symmetric Hausdorff distance between two point sets (the larger of the two directed
// ones), with a uniform grid for the nearest-point queries. Infinity when one is empty.
double hausdorff_distance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b);

// Both skeletons sampled at 1/200 of the larger height, compared (meters).
double skeleton_hausdorff(const Skeleton& a, const Skeleton& b);

// The skeleton with every segment's end moved by up to 3 % of the segment's length in a
// random direction (the same for a seed), children following: how a measured tree differs
// from the one that was grown (the robustness target of `sylva infer`'s tests and bench).
Skeleton jittered(Skeleton skeleton, std::uint64_t seed);

}  // namespace sylva
