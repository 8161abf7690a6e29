// Sylva octahedral impostor for Godot 3 (GLES3) (docs/impostors.md; a port of docs/impostor.glsl).
// Put it on the `impostor` mesh of an export with --impostor (the last LOD); set the
// textures to the glb's impostor_albedo and impostor_normal (or the PNGs beside an OBJ)
// and the uniforms to the layout's "views", "center" and "radius" (the node's extras or
// OUT_impostor.json). Godot imports glTF in its own axes (Y up, metres): no conversion.
shader_type spatial;
render_mode cull_disabled;

uniform sampler2D impostor_albedo : hint_albedo;  // import with Filter and Mipmaps on, Repeat off
uniform sampler2D impostor_normal;  // likewise; not as a normal map (sRGB off)
uniform float impostor_views = 8.0;
uniform vec3 impostor_center = vec3(0.0);
uniform float impostor_radius = 1.0;

varying vec3 quad_point;    // model space
varying vec3 camera_model;  // the camera in model space

vec2 sylva_encode(vec3 d) {
	d.y = max(d.y, 0.0);
	vec2 p = d.xz / (abs(d.x) + d.y + abs(d.z));
	return vec2(p.x + p.y, p.x - p.y);
}

vec3 sylva_decode(vec2 s) {
	vec2 p = vec2(s.x + s.y, s.x - s.y) * 0.5;
	return normalize(vec3(p.x, max(1.0 - abs(p.x) - abs(p.y), 0.0), p.y));
}

void sylva_frame(vec3 direction, out vec3 right, out vec3 up) {
	vec3 r = cross(vec3(0.0, 1.0, 0.0), direction);
	right = dot(r, r) > 1e-12 ? normalize(r) : vec3(1.0, 0.0, 0.0);
	up = cross(direction, right);
}

// One view's albedo where the ray through `point` meets its surface; its normal in `n`.
vec4 sylva_view(vec2 view, vec3 point, vec3 ray, out vec3 n) {
	vec3 direction = sylva_decode(view / (impostor_views - 1.0) * 2.0 - 1.0);
	vec3 right;
	vec3 up;
	sylva_frame(direction, right, up);
	vec3 from_center = point - impostor_center;
	float facing = min(dot(ray, direction), -1e-4);
	float depth = 0.0;
	vec2 uv = vec2(0.0);
	vec4 nd = vec4(0.5);
	for (int step = 0; step <= 2; step++) {
		vec3 hit = from_center + ray * ((depth - dot(from_center, direction)) / facing);
		vec2 tile = vec2(dot(hit, right), -dot(hit, up)) / impostor_radius * 0.5 + 0.5;
		if (tile.x < 0.0 || tile.y < 0.0 || tile.x > 1.0 || tile.y > 1.0) {
			n = vec3(0.0);
			return vec4(0.0);
		}
		uv = (view + tile) / impostor_views;
		nd = texture(impostor_normal, uv);
		depth = (nd.a - 0.5) * 2.0 * impostor_radius;
	}
	n = nd.rgb * 2.0 - 1.0;
	return texture(impostor_albedo, uv);
}

void vertex() {
	camera_model = (inverse(WORLD_MATRIX) * vec4(CAMERA_MATRIX[3].xyz, 1.0)).xyz;
	vec2 corner = (VERTEX.xy - impostor_center.xy) / impostor_radius;
	vec3 to_camera = normalize(camera_model - impostor_center);
	vec3 right;
	vec3 up;
	sylva_frame(to_camera, right, up);
	quad_point = impostor_center + impostor_radius * (corner.x * right + corner.y * up);
	VERTEX = quad_point;
	NORMAL = to_camera;
}

void fragment() {
	float last = impostor_views - 1.0;
	vec2 grid = (sylva_encode(normalize(camera_model - impostor_center)) * 0.5 + 0.5) * last;
	vec2 cell = clamp(floor(grid), vec2(0.0), vec2(last - 1.0));
	vec2 f = clamp(grid - cell, 0.0, 1.0);
	vec2 a = f.x + f.y <= 1.0 ? cell : cell + vec2(1.0);
	vec3 w = f.x + f.y <= 1.0 ? vec3(1.0 - f.x - f.y, f.x, f.y)
	                          : vec3(f.x + f.y - 1.0, 1.0 - f.y, 1.0 - f.x);
	vec3 ray = normalize(quad_point - camera_model);
	vec3 na;
	vec3 nb;
	vec3 nc;
	vec4 albedo = w.x * sylva_view(a, quad_point, ray, na) +
	              w.y * sylva_view(cell + vec2(1.0, 0.0), quad_point, ray, nb) +
	              w.z * sylva_view(cell + vec2(0.0, 1.0), quad_point, ray, nc);
	vec3 n = w.x * na + w.y * nb + w.z * nc;
	ALBEDO = albedo.rgb;
	ALPHA = min(albedo.a * 1.4, 1.0);  // the layout's coverage_gain, as the reference
	ALPHA_SCISSOR = 0.5;
	ROUGHNESS = 0.9;
	if (dot(n, n) > 0.0)
		NORMAL = normalize((INV_CAMERA_MATRIX * WORLD_MATRIX * vec4(normalize(n), 0.0)).xyz);
}
