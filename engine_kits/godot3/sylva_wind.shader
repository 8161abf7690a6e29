// Sylva wind for Godot 3 (3.2 and later): the Godot 4 shader (godot4/sylva_wind.gdshader)
// in Godot 3's syntax. It sways a tree exported with `sylva export --profile godot`, whose
// TEXCOORD_1 Godot imports as UV2 = (sway, flex), written as floats because Godot 3.2.3
// ignores glTF's `normalized` flag. The phase comes from the vertex's place (a gust
// travelling through the crown) and leaves flutter with their flex, so only UV2 is needed;
// the motion is docs/wind.glsl's. The colour is `albedo` times the vertex colour (glTF
// COLOR_0, the tint; white without one). sylva_post_import.gd gives every part of an
// imported tree a copy with the part's own colour as `albedo`.
shader_type spatial;
render_mode cull_disabled;

uniform vec4 albedo : hint_color = vec4(0.3, 0.55, 0.2, 1.0);
uniform vec2 wind_direction = vec2(1.0, 0.0);
uniform float wind_strength = 0.3;  // metres the top moves in a steady wind

void vertex() {
    float sway = UV2.x;
    float flex = UV2.y;
    float phase = 0.8 * VERTEX.x + 0.6 * VERTEX.z;
    vec3 along = vec3(wind_direction.x, 0.0, wind_direction.y);
    float gust = 0.65 + 0.35 * sin(0.9 * TIME) * sin(0.37 * TIME + 1.3);
    vec3 offset = along * wind_strength * sway * gust;
    offset += wind_strength * 0.35 * flex * sin(2.1 * TIME + phase) * (along + vec3(0.0, 0.3, 0.0));
    offset.y += wind_strength * 0.1 * flex * flex * sin(11.0 * TIME + 3.0 * phase);
    VERTEX += offset;
}

void fragment() {
    ALBEDO = albedo.rgb * COLOR.rgb;
    ROUGHNESS = 0.9;
}
