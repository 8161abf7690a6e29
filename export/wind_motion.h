// The motion the wind data (export/part_attributes.h) is made for, in C++: the same
// formula as docs/wind.glsl's sylva_wind() and the engine kits' wind shaders, so Sylva
// Studio's wind preview shows what an engine with that shader shows, and tests can check
// what the data does. The wind itself (strength, direction, gusts, flutter) is the tree's
// wind parameters (core/wind_params.h), which exports carry to the kits' materials.
// Pure functions of their arguments: safe from any thread.
#pragma once

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string_view>

#include "core/tree_params.h"

namespace sylva {

struct WindMotion {
    glm::vec2 direction{1.0f, 0.0f};  // unit, on the ground plane (x, z): where it blows to
    float strength = 0.3f;            // metres the top leans in a steady wind
    float gust_frequency = 0.15f;     // gusts per second; 0: a steady wind
    float flutter = 0.1f;             // leaf tips' flutter as a share of strength
};

// The wind parameters of `params` (wind_strength, wind_direction, ...) as a motion.
WindMotion wind_motion(const TreeParams& params);

// How hard the wind blows at `time` seconds, as a factor of the strength in [0.5, 1.5]:
// 1 + 0.5 * a smooth 1D gradient noise (Perlin 2002) of time * gust_frequency, whose
// gradients come from a float-only hash (Hoskins 2014) every shader language computes
// alike. Exactly 1 with gust_frequency 0 (and at every whole time * gust_frequency).
float wind_gust(float time, float gust_frequency);

// Where a vertex at `p` with wind data `wind` (sway, flex, phase, flutter) is at `time`
// seconds. A vertex with all four zero (the trunk's base) never moves; no vertex moves
// further than wind_reach(motion).
glm::vec3 wind_position(const glm::vec3& p, const glm::vec4& wind, float time,
                        const WindMotion& motion = {});

// The most any vertex moves under `motion`: 1.5 * strength * (1 + 0.35 * |(1, 0.3)| +
// flutter * |(0.5, 1)|), a gust's peak with every weight at 1.
float wind_reach(const WindMotion& motion);

// The motion as exports write it for the engine kits (glb material extras, FBX material
// user properties), each rounded to 6 decimals: sylva_wind_strength,
// sylva_wind_direction_x, sylva_wind_direction_z, sylva_wind_gust_frequency,
// sylva_wind_flutter (docs/engines.md, "Wind").
struct WindValue {
    std::string_view key;
    double value;
};
std::array<WindValue, 5> wind_values(const WindMotion& motion);

}  // namespace sylva
