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

const int SYLVA_RELIEF_STEPS = 64;       // the layout's relief_steps
const int SYLVA_RELIEF_REFINEMENTS = 3;  // relief_refinements
const float SYLVA_SURFACE_TEXELS = 5.0;  // surface_texels

// Whether `p` (from the centre) lies on the view's surface: its texel (read unfiltered, at
// its centre) is covered, and p lies from `band` behind the texel's depth to that depth.
bool sylva_on_surface(vec2 view, vec3 p, vec3 direction, vec3 right, vec3 up, float tile_px,
		float band, out vec2 uv) {
	vec2 tile = vec2(dot(p, right), -dot(p, up)) / impostor_radius * 0.5 + 0.5;
	uv = (view + tile) / impostor_views;
	if (tile.x < 0.0 || tile.y < 0.0 || tile.x >= 1.0 || tile.y >= 1.0) {
		return false;
	}
	vec2 texel = (view * tile_px + floor(tile * tile_px) + 0.5) / (impostor_views * tile_px);
	if (textureLod(impostor_albedo, texel, 0.0).a <= 0.0) {
		return false;
	}
	float depth = (textureLod(impostor_normal, texel, 0.0).a - 0.5) * 2.0 * impostor_radius;
	float along = dot(p, direction);
	return along <= depth && along >= depth - band;
}

// One view's albedo where the ray through `point` first meets its surface (a march through
// the view's depth, then halvings); its normal in `n`. Zero where the ray misses it.
vec4 sylva_view(vec2 view, vec3 point, vec3 ray, out vec3 n) {
	vec3 direction = sylva_decode(view / (impostor_views - 1.0) * 2.0 - 1.0);
	vec3 right;
	vec3 up;
	sylva_frame(direction, right, up);
	vec3 from_center = point - impostor_center;
	// The hit is read at the mip level of the quad's own footprint: the march branches.
	vec2 on_plane = (view + vec2(dot(from_center, right), -dot(from_center, up)) /
			impostor_radius * 0.5 + 0.5) / impostor_views;
	vec2 du = dFdx(on_plane);
	vec2 dv = dFdy(on_plane);
	n = vec3(0.0);
	if (dot(ray, direction) >= -1e-4) {
		return vec4(0.0);
	}
	float tile_px = float(textureSize(impostor_normal, 0).x) / impostor_views;
	float step_length = 2.0 * impostor_radius / float(SYLVA_RELIEF_STEPS);
	float band = SYLVA_SURFACE_TEXELS * 2.0 * impostor_radius / tile_px + step_length;
	vec2 uv;
	for (int i = 0; i <= SYLVA_RELIEF_STEPS; i++) {
		float s = impostor_radius - step_length * float(i);
		if (!sylva_on_surface(view, from_center - ray * s, direction, right, up, tile_px, band, uv)) {
			continue;
		}
		float front = s + step_length;
		float back = s;
		for (int k = 0; i > 0 && k < SYLVA_RELIEF_REFINEMENTS; k++) {
			float middle = 0.5 * (front + back);
			if (sylva_on_surface(view, from_center - ray * middle, direction, right, up, tile_px, band, uv)) {
				back = middle;
			} else {
				front = middle;
			}
		}
		sylva_on_surface(view, from_center - ray * back, direction, right, up, tile_px, band, uv);
		n = textureGrad(impostor_normal, uv, du, dv).rgb * 2.0 - 1.0;
		return textureGrad(impostor_albedo, uv, du, dv);
	}
	return vec4(0.0);
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
	vec4 ta = sylva_view(a, quad_point, ray, na);
	vec4 tb = sylva_view(cell + vec2(1.0, 0.0), quad_point, ray, nb);
	vec4 tc = sylva_view(cell + vec2(0.0, 1.0), quad_point, ray, nc);
	vec4 albedo = w.x * ta + w.y * tb + w.z * tc;
	// A view the ray misses adds no coverage; colour averages the views it hits.
	vec3 hits = w * vec3(ta.a > 0.0 ? 1.0 : 0.0, tb.a > 0.0 ? 1.0 : 0.0, tc.a > 0.0 ? 1.0 : 0.0);
	albedo.rgb /= max(hits.x + hits.y + hits.z, 1e-6);
	vec3 n = w.x * na + w.y * nb + w.z * nc;
	ALBEDO = albedo.rgb;
	ALPHA = min(albedo.a * 1.4, 1.0);  // the layout's coverage_gain, as the reference
	ALPHA_SCISSOR = 0.5;
	ROUGHNESS = 0.9;
	if (dot(n, n) > 0.0)
		NORMAL = normalize((INV_CAMERA_MATRIX * WORLD_MATRIX * vec4(normalize(n), 0.0)).xyz);
}
