#include "colonization/obstacle.h"

#include <cmath>

namespace sylva {

bool inside(const Obstacle& obstacle, const glm::vec3& p) {
    const glm::vec3 q = (p - obstacle.center) / (0.5f * obstacle.size);  // unit half extents
    switch (obstacle.shape) {
        case ObstacleShape::None:
            return false;
        case ObstacleShape::Sphere:
            return q.x * q.x + q.y * q.y + q.z * q.z <= 1.0f;
        case ObstacleShape::Box:
            return std::abs(q.x) <= 1.0f && std::abs(q.y) <= 1.0f && std::abs(q.z) <= 1.0f;
    }
    return false;
}

}  // namespace sylva
