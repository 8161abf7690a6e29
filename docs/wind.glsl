// Sylva wind: a reference vertex shader (GLSL 3.30) that sways an exported tree.
//
// Every vertex carries four values in [0, 1] (README "Wind"):
//   sway    the whole tree's bend: 0 at the ground, 1 at the top (quadratic)
//   flex    0 on the trunk, rising along each branch to 1 at its tip; 1 on leaves
//   phase   one per first-order branch (its sub-branches share it), crown piece and leaf
//   flutter leaves only: 0 at the leaf's base, 1 at its tip
// The generic profile stores them as COLOR_1 (vec4); unity, unreal and godot as
// TEXCOORD_1 = (sway, flex) and TEXCOORD_2 = (phase, flutter). Sylva Studio's wind toggle
// runs this same sylva_wind() (export/wind_motion.cpp).
#version 330 core

layout(location = 0) in vec3 position;  // metres, Y up
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 wind;      // COLOR_1, or vec4(TEXCOORD_1, TEXCOORD_2)

uniform mat4 model_view_projection;
uniform float time;                 // seconds
// The tree's wind, as the export carries it (glb material extras, FBX user properties):
uniform vec2 wind_direction;        // sylva_wind_direction_x/_z: unit, on the ground (x, z)
uniform float wind_strength;        // sylva_wind_strength: metres the top leans, e.g. 0.3
uniform float wind_gust_frequency;  // sylva_wind_gust_frequency: gusts per second, e.g. 0.15
uniform float wind_flutter;         // sylva_wind_flutter: leaf tips' share of strength, e.g. 0.1

out vec3 view_normal;

// Hoskins (2014), "Hash without Sine": [0, 1) from a float, alike in every shader language.
float sylva_hash(float p) {
    p = fract(p * 0.1031);
    p *= p + 33.33;
    p *= p + p;
    return fract(p);
}

// How hard the wind blows at time t, in [0.5, 1.5]: 1 plus half a 1D gradient noise
// (Perlin 2002's fade) of t * frequency; 1 for a steady wind (frequency 0).
float sylva_gust(float t, float frequency) {
    float x = t * frequency;
    float i = floor(x), f = x - i;
    float g0 = 2.0 * sylva_hash(i) - 1.0, g1 = 2.0 * sylva_hash(i + 1.0) - 1.0;
    float u = f * f * (3.0 - 2.0 * f);
    return 1.0 + mix(g0 * f, g1 * (f - 1.0), u);
}

vec3 sylva_wind(vec3 p, vec4 w, float t, vec2 direction, float strength, float gust_frequency,
                float flutter) {
    vec3 along = vec3(direction.x, 0.0, direction.y);
    float phase = 6.2831853 * w.z;
    float lean = strength * sylva_gust(t, gust_frequency);
    // The whole tree leans with the gusts.
    vec3 offset = along * lean * w.x;
    // Branches swing on their own rhythm, a little up and down too.
    offset += lean * 0.35 * w.y * sin(2.1 * t + phase) * (along + vec3(0.0, 0.3, 0.0));
    // Leaves flutter fast about their base, mostly up and down.
    offset += lean * flutter * w.w * sin(11.0 * t + 3.0 * phase + p.x + p.z) *
              vec3(0.5 * along.x, 1.0, 0.5 * along.z);
    return p + offset;
}

void main() {
    vec3 p = sylva_wind(position, wind, time, wind_direction, wind_strength, wind_gust_frequency,
                        wind_flutter);
    view_normal = normal;
    gl_Position = model_view_projection * vec4(p, 1.0);
}
