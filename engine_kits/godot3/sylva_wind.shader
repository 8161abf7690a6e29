// Sylva wind for Godot 3 (3.2 and later): the Godot 4 shader (godot4/sylva_wind.gdshader)
// in Godot 3's syntax. It sways a tree exported with `sylva export --profile godot`, whose
// TEXCOORD_1 Godot imports as UV2 = (sway, flex), written as floats because Godot 3.2.3
// ignores glTF's `normalized` flag. The phase comes from the vertex's place (a gust
// travelling through the crown) and leaves flutter with their flex, so only UV2 is needed;
// the motion is docs/wind.glsl's. The colour is `albedo` times the vertex colour (glTF
// COLOR_0, the tint; white without one). sylva_post_import.gd gives every part of an
// imported tree a copy with the part's own colour as `albedo` and the tree's wind.
shader_type spatial;
render_mode cull_disabled;

uniform vec4 albedo : hint_color = vec4(0.3, 0.55, 0.2, 1.0);
// The tree's wind: sylva_post_import.gd sets these from the glb's material extras.
uniform vec2 wind_direction = vec2(1.0, 0.0);  // unit, on the ground (x, z)
uniform float wind_strength = 0.3;             // metres the top leans in a steady wind
uniform float wind_gust_frequency = 0.15;      // gusts per second (0: steady)
uniform float wind_flutter = 0.1;              // leaf tips' flutter, a share of strength

// Hoskins (2014), "Hash without Sine": [0, 1) from a float.
float sylva_hash(float p) {
    p = fract(p * 0.1031);
    p *= p + 33.33;
    p *= p + p;
    return fract(p);
}

// How hard the wind blows at time t, in [0.5, 1.5] (docs/wind.glsl's sylva_gust).
float sylva_gust(float t, float frequency) {
    float x = t * frequency;
    float i = floor(x);
    float f = x - i;
    float g0 = 2.0 * sylva_hash(i) - 1.0;
    float g1 = 2.0 * sylva_hash(i + 1.0) - 1.0;
    float u = f * f * (3.0 - 2.0 * f);
    return 1.0 + mix(g0 * f, g1 * (f - 1.0), u);
}

void vertex() {
    float sway = UV2.x;
    float flex = UV2.y;
    float phase = 0.8 * VERTEX.x + 0.6 * VERTEX.z;
    vec3 along = vec3(wind_direction.x, 0.0, wind_direction.y);
    float lean = wind_strength * sylva_gust(TIME, wind_gust_frequency);
    vec3 offset = along * lean * sway;
    offset += lean * 0.35 * flex * sin(2.1 * TIME + phase) * (along + vec3(0.0, 0.3, 0.0));
    offset += lean * wind_flutter * flex * flex * sin(11.0 * TIME + 3.0 * phase) *
              vec3(0.5 * along.x, 1.0, 0.5 * along.z);
    VERTEX += offset;
}

void fragment() {
    ALBEDO = albedo.rgb * COLOR.rgb;
    ROUGHNESS = 0.9;
}
