// Signed distance to a capped cone (a tapered branch segment), after Inigo Quilez's exact
// sdCappedCone(p, a, b, ra, rb). Negative inside, Lipschitz 1.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <span>

namespace sylva {

struct CappedCone {
    glm::vec3 a{0.0f};
    glm::vec3 b{0.0f};
    float ra = 0.0f;
    float rb = 0.0f;
};

// A cone with the terms of distance() that depend on its ends alone computed once, for
// fields that evaluate one cone at many points. distance(prepare(c), p) is distance(c, p)
// bit for bit: the same operations on the same values, only some done earlier.
struct PreparedCone {
    glm::vec3 a{0.0f};
    glm::vec3 ba{0.0f};  // b - a
    float ra = 0.0f;
    float rb = 0.0f;
    float rba = 0.0f;   // rb - ra
    float baba = 0.0f;  // dot(ba, ba)
    float k = 0.0f;     // rba^2 + baba
};

inline PreparedCone prepare(const CappedCone& cone) {
    PreparedCone c;
    c.a = cone.a;
    c.ba = cone.b - cone.a;
    c.ra = cone.ra;
    c.rb = cone.rb;
    c.rba = cone.rb - cone.ra;
    c.baba = glm::dot(c.ba, c.ba);
    c.k = c.rba * c.rba + c.baba;
    return c;
}

// Inline so the fields' hot loops inline it.
inline float distance(const PreparedCone& cone, const glm::vec3& p) {
    // Inigo Quilez, "distance functions": exact capped cone with arbitrary end points.
    const glm::vec3 pa = p - cone.a;
    const float baba = cone.baba;
    if (baba <= 0.0f) return glm::length(pa) - std::max(cone.ra, cone.rb);  // a sphere
    const float papa = glm::dot(pa, pa);
    const float paba = glm::dot(pa, cone.ba) / baba;
    const float x = std::sqrt(std::max(papa - paba * paba * baba, 0.0f));
    const float cax = std::max(0.0f, x - (paba < 0.5f ? cone.ra : cone.rb));
    const float cay = std::abs(paba - 0.5f) - 0.5f;
    const float f = std::clamp((cone.rba * (x - cone.ra) + paba * baba) / cone.k, 0.0f, 1.0f);
    const float cbx = x - cone.ra - f * cone.rba;
    const float cby = paba - f;
    const float s = (cbx < 0.0f && cay < 0.0f) ? -1.0f : 1.0f;
    return s * std::sqrt(std::min(cax * cax + cay * cay * baba, cbx * cbx + cby * cby * baba));
}

float distance(const CappedCone& cone, const glm::vec3& p);

// Hard union (minimum) over all cones; +infinity for an empty list. Every primitive is
// evaluated: fine for small trees, culled by a spatial structure in a later stage.
float union_distance(std::span<const CappedCone> cones, const glm::vec3& p);

}  // namespace sylva
