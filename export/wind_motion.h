// The motion the wind data (export/part_attributes.h) is made for, in C++: the same
// formula as docs/wind.glsl's sylva_wind(), so Sylva Studio's wind toggle shows what an
// engine with that shader shows, and tests can check what the data does.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace sylva {

struct WindMotion {
    glm::vec2 direction{1.0f, 0.0f};  // unit, on the ground plane (x, z)
    float strength = 0.3f;            // metres the top moves in a steady wind
};

// Where a vertex at `p` with wind data `wind` (sway, flex, phase, flutter) is at `time`
// seconds. A vertex with all four zero (the trunk's base) never moves.
glm::vec3 wind_position(const glm::vec3& p, const glm::vec4& wind, float time,
                        const WindMotion& motion = {});

}  // namespace sylva
