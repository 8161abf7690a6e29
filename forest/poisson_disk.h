// Poisson disk sampling (Bridson, "Fast Poisson Disk Sampling in Arbitrary Dimensions",
// SIGGRAPH 2007 sketch): points in a rectangle no two of which are closer than a minimum
// distance, spread evenly but without a grid's regularity. O(n) with a background grid of
// cells r / sqrt(2) wide, each holding at most one point.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

namespace sylva::forest {

struct PoissonSettings {
    double min_distance = 4.0;  // meters
    int attempts = 30;          // Bridson's k: candidates around an active point
    std::uint64_t seed = 1;
    // Safety cap: a tiny distance over a big area stops here.
    std::size_t max_points = 1'000'000;
};

// Points in [lo, hi] (x and y), pairwise at least min_distance apart, in the order they were
// accepted. Deterministic for the settings. Empty for an empty rectangle; throws InputError
// for a min_distance that is not positive or would need more than max_points points.
std::vector<glm::dvec2> poisson_disk(glm::dvec2 lo, glm::dvec2 hi, const PoissonSettings& settings);

}  // namespace sylva::forest
