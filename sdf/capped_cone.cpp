#include "sdf/capped_cone.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace sylva {

float distance(const CappedCone& cone, const glm::vec3& p) {
    // Inigo Quilez, "distance functions": exact capped cone with arbitrary end points.
    const float rba = cone.rb - cone.ra;
    const glm::vec3 ba = cone.b - cone.a;
    const glm::vec3 pa = p - cone.a;
    const float baba = glm::dot(ba, ba);
    if (baba <= 0.0f) return glm::length(pa) - std::max(cone.ra, cone.rb);  // a sphere
    const float papa = glm::dot(pa, pa);
    const float paba = glm::dot(pa, ba) / baba;
    const float x = std::sqrt(std::max(papa - paba * paba * baba, 0.0f));
    const float cax = std::max(0.0f, x - (paba < 0.5f ? cone.ra : cone.rb));
    const float cay = std::abs(paba - 0.5f) - 0.5f;
    const float k = rba * rba + baba;
    const float f = std::clamp((rba * (x - cone.ra) + paba * baba) / k, 0.0f, 1.0f);
    const float cbx = x - cone.ra - f * rba;
    const float cby = paba - f;
    const float s = (cbx < 0.0f && cay < 0.0f) ? -1.0f : 1.0f;
    return s * std::sqrt(std::min(cax * cax + cay * cay * baba, cbx * cbx + cby * cby * baba));
}

float union_distance(std::span<const CappedCone> cones, const glm::vec3& p) {
    float d = std::numeric_limits<float>::infinity();
    for (const CappedCone& c : cones) d = std::min(d, distance(c, p));
    return d;
}

}  // namespace sylva
