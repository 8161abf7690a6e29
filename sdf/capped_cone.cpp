#include "sdf/capped_cone.h"

#include <algorithm>
#include <limits>

namespace sylva {

float distance(const CappedCone& cone, const glm::vec3& p) {
    return distance(prepare(cone), p);
}

float union_distance(std::span<const CappedCone> cones, const glm::vec3& p) {
    float d = std::numeric_limits<float>::infinity();
    for (const CappedCone& c : cones) d = std::min(d, distance(c, p));
    return d;
}

}  // namespace sylva
