// Signed distance to a capped cone (a tapered branch segment), after Inigo Quilez's exact
// sdCappedCone(p, a, b, ra, rb). Negative inside, Lipschitz 1.
#pragma once

#include <glm/vec3.hpp>
#include <span>

namespace sylva {

struct CappedCone {
    glm::vec3 a{0.0f};
    glm::vec3 b{0.0f};
    float ra = 0.0f;
    float rb = 0.0f;
};

float distance(const CappedCone& cone, const glm::vec3& p);

// Hard union (minimum) over all cones; +infinity for an empty list. Every primitive is
// evaluated: fine for small trees, culled by a spatial structure in a later stage.
float union_distance(std::span<const CappedCone> cones, const glm::vec3& p);

}  // namespace sylva
