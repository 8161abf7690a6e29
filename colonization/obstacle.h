// An obstacle (Liebemann 2017, 3.3: "obstacles ... which limit the space"): a solid the crown
// grows around. No attraction point is placed in it and no node grows into it, so
// branches stop at a wall or part around a boulder.
#pragma once

#include <glm/vec3.hpp>

namespace sylva {

enum class ObstacleShape { None = 0, Sphere = 1, Box = 2 };

struct Obstacle {
    ObstacleShape shape = ObstacleShape::None;
    glm::vec3 center{0.0f};
    // Full extents along x, y and z; a sphere with unequal extents is an ellipsoid.
    glm::vec3 size{1.0f};
};

// True when p lies inside the obstacle (boundary included); always false for None.
bool inside(const Obstacle& obstacle, const glm::vec3& p);

}  // namespace sylva
