// Sylva octahedral impostor: the reference shader (GLSL 3.30) that draws the impostor level
// of an export (docs/impostors.md) as one quad turned to the camera. Sylva Studio compiles
// this file as it is, once with SYLVA_IMPOSTOR_VERTEX and once with SYLVA_IMPOSTOR_FRAGMENT
// defined after its #version line (ui/impostor_view.cpp); the engine kits' shaders
// (engine_kits/*/impostor_*) are ports of it, and impostor/atlas_sampler.cpp is the same
// arithmetic on the CPU, which the fidelity tests check against the tree.
//
// Everything is in the model's own space (metres, Y up, right-handed: as exported): the
// layout's center and radius, the camera position, the quad's corners.
//   albedo atlas: sRGB colour, alpha = coverage (blended, times 1.4, alpha-tested at 0.5)
//   normal atlas: rgb = object-space normal * 0.5 + 0.5, a = 0.5 + depth / (2 radius)
// View (i, j) of N x N fills column i, row j (rows top down); its direction is the
// hemi-octahedral decoding of (i, j) / (N - 1) * 2 - 1. The three views around the
// camera's direction are blended; each is read where the camera's ray meets that view's
// surface, found by marching the ray through the view's depth (relief mapping: 64 steps
// from radius in front of the centre to radius behind it, then 3 halvings), so they line
// up at every depth. A texel is surface from its depth back to 5 texels plus a step behind
// it (the layout's relief_steps, relief_refinements, surface_texels).

uniform sampler2D impostor_albedo;  // an sRGB texture (GL_SRGB8_ALPHA8), mipmapped
uniform sampler2D impostor_normal;  // linear (GL_RGBA8), mipmapped
uniform float impostor_views;       // N, e.g. 8
uniform vec3 impostor_center;       // the layout's "center"
uniform float impostor_radius;      // the layout's "radius"
uniform vec3 camera_position;       // the camera in the model's space
uniform mat4 model_view_projection;

// Image rows run top down in the atlas; textures uploaded row 0 first have t = 0 there.
vec2 sylva_hemi_octahedral_encode(vec3 d) {
    d.y = max(d.y, 0.0);
    vec2 p = d.xz / (abs(d.x) + d.y + abs(d.z));
    return vec2(p.x + p.y, p.x - p.y);
}

vec3 sylva_hemi_octahedral_decode(vec2 s) {
    vec2 p = vec2(s.x + s.y, s.x - s.y) * 0.5;
    return normalize(vec3(p.x, max(1.0 - abs(p.x) - abs(p.y), 0.0), p.y));
}

// The camera a view was captured with: right, up (direction points to the camera).
void sylva_view_frame(vec3 direction, out vec3 right, out vec3 up) {
    vec3 r = cross(vec3(0.0, 1.0, 0.0), direction);
    right = dot(r, r) > 1e-12 ? normalize(r) : vec3(1.0, 0.0, 0.0);
    up = cross(direction, right);
}

vec3 sylva_view_direction(vec2 view) {
    return sylva_hemi_octahedral_decode(view / (impostor_views - 1.0) * 2.0 - 1.0);
}

#ifdef SYLVA_IMPOSTOR_VERTEX
layout(location = 0) in vec3 position;  // a corner of the exported quad
out vec3 quad_point;                    // the corner, turned to face the camera

void main() {
    // The exported quad spans center +- radius along x and y: its corner in [-1, 1]^2.
    vec2 corner = (position.xy - impostor_center.xy) / impostor_radius;
    vec3 right, up;
    sylva_view_frame(normalize(camera_position - impostor_center), right, up);
    quad_point = impostor_center + impostor_radius * (corner.x * right + corner.y * up);
    gl_Position = model_view_projection * vec4(quad_point, 1.0);
}
#endif

#ifdef SYLVA_IMPOSTOR_FRAGMENT
in vec3 quad_point;
// What the studio shows: albedo lit by the baked normal, gamma-encoded for an 8-bit
// framebuffer as the studio's other renderers write it.
out vec4 sylva_color;
uniform vec3 light_direction;  // toward the light, model space, unit

// One view's texel where the camera's ray through `point` first meets its surface: albedo
// in .albedo, object-space normal in .normal; both zero where the ray misses it.
struct SylvaTexel {
    vec4 albedo;
    vec3 normal;
};

const int SYLVA_RELIEF_STEPS = 64;       // the layout's relief_steps
const int SYLVA_RELIEF_REFINEMENTS = 3;  // relief_refinements
const float SYLVA_SURFACE_TEXELS = 5.0;  // surface_texels

// Whether `p` (from the centre) lies on the view's surface: its texel (read unfiltered, at
// its centre) is covered, and p lies from `band` behind the texel's depth to that depth.
// `uv` is p's place in the atlas.
bool sylva_on_surface(vec2 view, vec3 p, vec3 direction, vec3 right, vec3 up, float tile_px,
                      float band, out vec2 uv) {
    vec2 tile = vec2(dot(p, right), -dot(p, up)) / impostor_radius * 0.5 + 0.5;
    uv = (view + tile) / impostor_views;
    if (any(lessThan(tile, vec2(0.0))) || any(greaterThanEqual(tile, vec2(1.0)))) return false;
    vec2 texel = (view * tile_px + floor(tile * tile_px) + 0.5) / (impostor_views * tile_px);
    if (textureLod(impostor_albedo, texel, 0.0).a <= 0.0) return false;
    float depth = (textureLod(impostor_normal, texel, 0.0).a - 0.5) * 2.0 * impostor_radius;
    float along = dot(p, direction);
    return along <= depth && along >= depth - band;
}

SylvaTexel sylva_impostor_view(vec2 view, vec3 point, vec3 ray) {
    vec3 direction = sylva_view_direction(view), right, up;
    sylva_view_frame(direction, right, up);
    vec3 from_center = point - impostor_center;
    // The hit is read with the mip level of the quad's own footprint: the march branches per
    // pixel, where implicit derivatives are undefined.
    vec2 on_plane = (view + vec2(dot(from_center, right), -dot(from_center, up)) /
                                impostor_radius * 0.5 + 0.5) / impostor_views;
    vec2 du = dFdx(on_plane), dv = dFdy(on_plane);
    SylvaTexel none = SylvaTexel(vec4(0.0), vec3(0.0));
    if (dot(ray, direction) >= -1e-4) return none;  // the view looks at the quad edge-on
    float tile_px = float(textureSize(impostor_normal, 0).x) / impostor_views;
    float step_length = 2.0 * impostor_radius / float(SYLVA_RELIEF_STEPS);
    float band = SYLVA_SURFACE_TEXELS * 2.0 * impostor_radius / tile_px + step_length;
    vec2 uv;
    for (int i = 0; i <= SYLVA_RELIEF_STEPS; ++i) {
        float s = impostor_radius - step_length * float(i);  // toward the camera from the quad
        if (!sylva_on_surface(view, from_center - ray * s, direction, right, up, tile_px, band, uv))
            continue;
        float front = s + step_length, back = s;  // the first hit lies between
        for (int k = 0; i > 0 && k < SYLVA_RELIEF_REFINEMENTS; ++k) {
            float middle = 0.5 * (front + back);
            if (sylva_on_surface(view, from_center - ray * middle, direction, right, up, tile_px,
                                 band, uv))
                back = middle;
            else
                front = middle;
        }
        sylva_on_surface(view, from_center - ray * back, direction, right, up, tile_px, band, uv);
        return SylvaTexel(textureGrad(impostor_albedo, uv, du, dv),
                          textureGrad(impostor_normal, uv, du, dv).rgb * 2.0 - 1.0);
    }
    return none;
}

// The blend of the three views around the camera's direction.
SylvaTexel sylva_impostor(vec3 point, vec3 camera) {
    float last = impostor_views - 1.0;
    vec2 grid = (sylva_hemi_octahedral_encode(normalize(camera - impostor_center)) * 0.5 + 0.5) * last;
    vec2 cell = clamp(floor(grid), vec2(0.0), vec2(last - 1.0));
    vec2 f = clamp(grid - cell, 0.0, 1.0);
    vec2 a, b = cell + vec2(1.0, 0.0), c = cell + vec2(0.0, 1.0);
    vec3 w;
    if (f.x + f.y <= 1.0) {
        a = cell;
        w = vec3(1.0 - f.x - f.y, f.x, f.y);
    } else {
        a = cell + vec2(1.0);
        w = vec3(f.x + f.y - 1.0, 1.0 - f.y, 1.0 - f.x);
    }
    vec3 ray = normalize(point - camera);
    SylvaTexel ta = sylva_impostor_view(a, point, ray);
    SylvaTexel tb = sylva_impostor_view(b, point, ray);
    SylvaTexel tc = sylva_impostor_view(c, point, ray);
    // A view the ray misses adds no coverage; colour averages the views it hits.
    vec3 hits = w * vec3(ta.albedo.a > 0.0, tb.albedo.a > 0.0, tc.albedo.a > 0.0);
    SylvaTexel sum;
    sum.albedo = w.x * ta.albedo + w.y * tb.albedo + w.z * tc.albedo;
    sum.albedo.rgb /= max(hits.x + hits.y + hits.z, 1e-6);
    // Coverage gain (the layout's coverage_gain): thin parts the three views do not quite
    // line up keep only a share of their coverage each; the test passes them from 0.36 on.
    sum.albedo.a = min(sum.albedo.a * 1.4, 1.0);
    vec3 n = w.x * ta.normal + w.y * tb.normal + w.z * tc.normal;
    sum.normal = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 1.0, 0.0);
    return sum;
}

void main() {
    SylvaTexel t = sylva_impostor(quad_point, camera_position);
    if (t.albedo.a < 0.5) discard;
    float light = 0.35 + 0.65 * max(dot(t.normal, light_direction), 0.0);
    sylva_color = vec4(pow(clamp(t.albedo.rgb * light, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
#endif
