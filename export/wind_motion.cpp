#include "export/wind_motion.h"

#include <cmath>

namespace sylva {

glm::vec3 wind_position(const glm::vec3& p, const glm::vec4& w, float t, const WindMotion& m) {
    const glm::vec3 along(m.direction.x, 0.0f, m.direction.y);
    const float phase = 6.2831853f * w.z;
    const float gust = 0.65f + 0.35f * std::sin(0.9f * t) * std::sin(0.37f * t + 1.3f);
    glm::vec3 offset = along * m.strength * w.x * gust;
    offset += m.strength * 0.35f * w.y * std::sin(2.1f * t + phase) *
              (along + glm::vec3(0.0f, 0.3f, 0.0f));
    offset.y += m.strength * 0.1f * w.w * std::sin(11.0f * t + 3.0f * phase + p.x + p.z);
    return p + offset;
}

}  // namespace sylva
