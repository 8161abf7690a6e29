// Sylva octahedral impostor for Unity (docs/impostors.md; a port of docs/impostor.glsl):
// HLSL functions for a hand-written shader (impostor_SylvaImpostor.shader includes this
// file) or a Shader Graph Custom Function node (File mode: SylvaImpostorVertex_float in the
// vertex stage's Position, SylvaImpostorFragment_float for Base Color, Alpha, Normal).
//
// Unity's glTF importers (glTFast, UnityGLTF) and its FBX import mirror X to turn glTF's
// right-handed space into Unity's left-handed one: `mirror_x` = 1 undoes that (the default);
// 0 for an import that keeps the axes. Sampled UVs put v = 0 at the image's bottom row, as
// Unity imports PNGs. Center and radius are the layout's (metres, the export's axes).

float3 SylvaMirror(float3 v, float mirror_x) {
    return float3(mirror_x > 0.5 ? -v.x : v.x, v.y, v.z);
}

float2 SylvaEncode(float3 d) {
    d.y = max(d.y, 0.0);
    float2 p = d.xz / (abs(d.x) + d.y + abs(d.z));
    return float2(p.x + p.y, p.x - p.y);
}

float3 SylvaDecode(float2 s) {
    float2 p = float2(s.x + s.y, s.x - s.y) * 0.5;
    return normalize(float3(p.x, max(1.0 - abs(p.x) - abs(p.y), 0.0), p.y));
}

void SylvaFrame(float3 direction, out float3 right, out float3 up) {
    float3 r = cross(float3(0.0, 1.0, 0.0), direction);
    right = dot(r, r) > 1e-12 ? normalize(r) : float3(1.0, 0.0, 0.0);
    up = cross(direction, right);
}

#define SYLVA_RELIEF_STEPS 64       // the layout's relief_steps
#define SYLVA_RELIEF_REFINEMENTS 3  // relief_refinements
#define SYLVA_SURFACE_TEXELS 5.0    // surface_texels

// Whether `p` (from the centre, Sylva's axes) lies on the view's surface: its texel (read
// unfiltered, at its centre) is covered, and p lies from `band` behind the texel's depth to
// that depth. `uv` is p's place in the atlas (Unity's v).
bool SylvaOnSurface(Texture2D albedo, Texture2D normal, SamplerState s, float views,
                    float radius, float2 view, float3 p, float3 direction, float3 right,
                    float3 up, float tile_px, float band, out float2 uv) {
    float2 tile = float2(dot(p, right), -dot(p, up)) / radius * 0.5 + 0.5;
    uv = (view + tile) / views;
    uv.y = 1.0 - uv.y;  // Unity: v = 0 at the bottom row
    if (any(tile < 0.0) || any(tile >= 1.0)) return false;
    float2 texel = (view * tile_px + floor(tile * tile_px) + 0.5) / (views * tile_px);
    texel.y = 1.0 - texel.y;
    if (albedo.SampleLevel(s, texel, 0.0).a <= 0.0) return false;
    float depth = (normal.SampleLevel(s, texel, 0.0).a - 0.5) * 2.0 * radius;
    float along = dot(p, direction);
    return along <= depth && along >= depth - band;
}

// One view's albedo where the ray through `p` (Sylva's axes) first meets its surface (a
// march through the view's depth, then halvings); normal in n. Zero where the ray misses.
float4 SylvaView(Texture2D albedo, Texture2D normal, SamplerState s, float views, float3 center,
                 float radius, float2 view, float3 p, float3 ray, out float3 n) {
    float3 direction = SylvaDecode(view / (views - 1.0) * 2.0 - 1.0);
    float3 right, up;
    SylvaFrame(direction, right, up);
    float3 from_center = p - center;
    // The hit is read at the mip level of the quad's own footprint: the march branches.
    float2 on_plane = (view + float2(dot(from_center, right), -dot(from_center, up)) / radius *
                       0.5 + 0.5) / views;
    on_plane.y = 1.0 - on_plane.y;
    float2 du = ddx(on_plane), dv = ddy(on_plane);
    n = 0.0;
    if (dot(ray, direction) >= -1e-4) return 0.0;
    float width, height;
    normal.GetDimensions(width, height);
    float tile_px = width / views;
    float step_length = 2.0 * radius / SYLVA_RELIEF_STEPS;
    float band = SYLVA_SURFACE_TEXELS * 2.0 * radius / tile_px + step_length;
    float2 uv;
    [loop] for (int i = 0; i <= SYLVA_RELIEF_STEPS; ++i) {
        float t = radius - step_length * i;
        if (!SylvaOnSurface(albedo, normal, s, views, radius, view, from_center - ray * t,
                            direction, right, up, tile_px, band, uv))
            continue;
        float front = t + step_length, back = t;
        for (int k = 0; i > 0 && k < SYLVA_RELIEF_REFINEMENTS; ++k) {
            float middle = 0.5 * (front + back);
            if (SylvaOnSurface(albedo, normal, s, views, radius, view, from_center - ray * middle,
                               direction, right, up, tile_px, band, uv))
                back = middle;
            else
                front = middle;
        }
        SylvaOnSurface(albedo, normal, s, views, radius, view, from_center - ray * back,
                       direction, right, up, tile_px, band, uv);
        n = normal.SampleGrad(s, uv, du, dv).rgb * 2.0 - 1.0;
        return albedo.SampleGrad(s, uv, du, dv);
    }
    return 0.0;
}

// Vertex stage: the exported quad's corner `position_os` (object space) turned to face
// `camera_os`; returns the new object-space position.
void SylvaImpostorVertex_float(float3 position_os, float3 camera_os, float views, float3 center,
                               float radius, float mirror_x, out float3 result) {
    float3 p = SylvaMirror(position_os, mirror_x);
    float3 cam = SylvaMirror(camera_os, mirror_x);
    float2 corner = (p.xy - center.xy) / radius;
    float3 right, up;
    SylvaFrame(normalize(cam - center), right, up);
    result = SylvaMirror(center + radius * (corner.x * right + corner.y * up), mirror_x);
}

// Fragment stage: albedo (sRGB texture, sampled as linear colour), alpha (clip at 0.5) and
// the object-space normal at the object-space point `position_os` on the turned quad.
void SylvaImpostorFragment_float(Texture2D albedo, Texture2D normal, SamplerState s,
                                 float3 position_os, float3 camera_os, float views,
                                 float3 center, float radius, float mirror_x,
                                 out float3 color, out float alpha, out float3 normal_os) {
    float3 p = SylvaMirror(position_os, mirror_x);
    float3 cam = SylvaMirror(camera_os, mirror_x);
    float last = views - 1.0;
    float2 grid = (SylvaEncode(normalize(cam - center)) * 0.5 + 0.5) * last;
    float2 cell = clamp(floor(grid), 0.0, last - 1.0);
    float2 f = saturate(grid - cell);
    bool lower = f.x + f.y <= 1.0;
    float2 a = lower ? cell : cell + 1.0;
    float3 w = lower ? float3(1.0 - f.x - f.y, f.x, f.y) : float3(f.x + f.y - 1.0, 1.0 - f.y, 1.0 - f.x);
    float3 ray = normalize(p - cam);
    float3 na, nb, nc;
    float4 ta = SylvaView(albedo, normal, s, views, center, radius, a, p, ray, na);
    float4 tb = SylvaView(albedo, normal, s, views, center, radius, cell + float2(1, 0), p, ray, nb);
    float4 tc = SylvaView(albedo, normal, s, views, center, radius, cell + float2(0, 1), p, ray, nc);
    float4 c = w.x * ta + w.y * tb + w.z * tc;
    // A view the ray misses adds no coverage; colour averages the views it hits.
    float3 hits = w * float3(ta.a > 0.0, tb.a > 0.0, tc.a > 0.0);
    c.rgb /= max(hits.x + hits.y + hits.z, 1e-6);
    float3 n = w.x * na + w.y * nb + w.z * nc;
    color = c.rgb;
    alpha = min(c.a * 1.4, 1.0);  // the layout's coverage_gain, as the reference
    normal_os = SylvaMirror(dot(n, n) > 0.0 ? normalize(n) : float3(0, 1, 0), mirror_x);
}
