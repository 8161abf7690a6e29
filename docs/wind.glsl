// Sylva wind: a reference vertex shader (GLSL 3.30) that sways an exported tree.
//
// Every vertex carries four values in [0, 1] (README "Wind"):
//   sway    the whole tree's bend: 0 at the ground, 1 at the top (quadratic)
//   flex    0 on the trunk, rising along each branch to 1 at its tip; 1 on leaves
//   phase   one per first-order branch (its sub-branches share it), crown piece and leaf
//   flutter leaves only: 0 at the leaf's base, 1 at its tip
// The generic profile stores them as COLOR_1 (vec4); unity, unreal and godot as
// TEXCOORD_1 = (sway, flex) and TEXCOORD_2 = (phase, flutter). Sylva Studio's wind toggle
// runs this same sylva_wind() (ui/wind_view.cpp).
#version 330 core

layout(location = 0) in vec3 position;  // metres, Y up
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 wind;      // COLOR_1, or vec4(TEXCOORD_1, TEXCOORD_2)

uniform mat4 model_view_projection;
uniform float time;            // seconds
uniform vec2 wind_direction;   // unit, on the ground plane (x, z)
uniform float wind_strength;   // metres the top moves in a steady wind, e.g. 0.3

out vec3 view_normal;

vec3 sylva_wind(vec3 p, vec4 w, float t, vec2 direction, float strength) {
    vec3 along = vec3(direction.x, 0.0, direction.y);
    float phase = 6.2831853 * w.z;
    // The whole tree leans with the gusts, slowly.
    float gust = 0.65 + 0.35 * sin(0.9 * t) * sin(0.37 * t + 1.3);
    vec3 offset = along * strength * w.x * gust;
    // Branches swing on their own rhythm, a little up and down too.
    offset += strength * 0.35 * w.y * sin(2.1 * t + phase) * (along + vec3(0.0, 0.3, 0.0));
    // Leaves flutter fast about their base.
    offset.y += strength * 0.1 * w.w * sin(11.0 * t + 3.0 * phase + p.x + p.z);
    return p + offset;
}

void main() {
    vec3 p = sylva_wind(position, wind, time, wind_direction, wind_strength);
    view_normal = normal;
    gl_Position = model_view_projection * vec4(p, 1.0);
}
