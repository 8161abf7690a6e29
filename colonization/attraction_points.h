// Attraction points (Liebemann 2017, 3.3 and 5.3 "random distribution of the points"): N points
// placed in an envelope, either independently uniform or along a low-discrepancy sequence
// that fills the space more evenly (fewer clumps, fewer empty pockets). Seeded: the same
// seed gives the same points on every machine.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "colonization/envelope.h"
#include "core/region.h"

namespace sylva {

enum class PointDistribution {
    Uniform = 0,  // independent uniform samples (rejection in the envelope's box)
    Halton = 1,   // Halton sequence in bases 2, 3, 5, shifted by a seeded random offset
};

// `count` points inside the envelope. Returns fewer only for an envelope so thin that
// rejection sampling cannot find them (after 100 tries per point).
std::vector<glm::vec3> attraction_points(const Envelope& envelope, int count,
                                         PointDistribution distribution, std::uint64_t seed);

// The same in any solid: candidates drawn in region.bounds, kept where region.contains
// (another template's crown, an envelope minus an obstacle). An envelope's region gives
// the points above, bit for bit.
std::vector<glm::vec3> attraction_points(const Region& region, int count,
                                         PointDistribution distribution, std::uint64_t seed);

}  // namespace sylva
