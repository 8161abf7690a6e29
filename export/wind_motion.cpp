#include "export/wind_motion.h"

#include <cmath>
#include <glm/trigonometric.hpp>

#include "core/wind_params.h"

namespace sylva {
namespace {

float fract(float x) {
    return x - std::floor(x);
}

// Hoskins (2014), "Hash without Sine": a value in [0, 1) from a float, with the same steps
// in GLSL, HLSL and Godot's shader language (no integers, no sin of large arguments).
float hash11(float p) {
    p = fract(p * 0.1031f);
    p *= p + 33.33f;
    p *= p + p;
    return fract(p);
}

// 1D gradient noise (Perlin 2002's fade), in [-1, 1], 0 at whole x.
float gust_noise(float x) {
    const float i = std::floor(x), f = x - i;
    const float g0 = 2.0f * hash11(i) - 1.0f, g1 = 2.0f * hash11(i + 1.0f) - 1.0f;
    const float u = f * f * (3.0f - 2.0f * f);
    return 2.0f * ((1.0f - u) * g0 * f + u * g1 * (f - 1.0f));
}

}  // namespace

WindMotion wind_motion(const TreeParams& params) {
    const WindParams& w = params.blocks.get<WindParams>();
    const float r = glm::radians(static_cast<float>(w.direction));
    return {{std::cos(r), std::sin(r)},
            static_cast<float>(w.strength),
            static_cast<float>(w.gust_frequency),
            static_cast<float>(w.flutter)};
}

float wind_gust(float t, float gust_frequency) {
    return 1.0f + 0.5f * gust_noise(t * gust_frequency);
}

glm::vec3 wind_position(const glm::vec3& p, const glm::vec4& w, float t, const WindMotion& m) {
    const glm::vec3 along(m.direction.x, 0.0f, m.direction.y);
    const float phase = 6.2831853f * w.z;
    const float lean = m.strength * wind_gust(t, m.gust_frequency);
    // The whole tree leans with the gusts.
    glm::vec3 offset = along * lean * w.x;
    // Branches swing on their own rhythm, a little up and down too.
    offset += lean * 0.35f * w.y * std::sin(2.1f * t + phase) * (along + glm::vec3(0, 0.3f, 0));
    // Leaves flutter fast about their base, mostly up and down.
    offset += lean * m.flutter * w.w * std::sin(11.0f * t + 3.0f * phase + p.x + p.z) *
              glm::vec3(0.5f * along.x, 1.0f, 0.5f * along.z);
    return p + offset;
}

std::array<WindValue, 5> wind_values(const WindMotion& m) {
    // + 0.0 turns -0 (a cosine of 90 degrees rounded) into 0.
    auto rounded = [](float v) { return std::round(static_cast<double>(v) * 1e6) / 1e6 + 0.0; };
    return {{{"sylva_wind_strength", rounded(m.strength)},
             {"sylva_wind_direction_x", rounded(m.direction.x)},
             {"sylva_wind_direction_z", rounded(m.direction.y)},
             {"sylva_wind_gust_frequency", rounded(m.gust_frequency)},
             {"sylva_wind_flutter", rounded(m.flutter)}}};
}

float wind_reach(const WindMotion& m) {
    return 1.5f * m.strength * (1.0f + 0.35f * std::sqrt(1.09f) + m.flutter * std::sqrt(1.25f));
}

}  // namespace sylva
