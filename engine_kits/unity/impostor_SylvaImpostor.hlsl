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

// One view's albedo where the ray through `p` (Sylva's axes) meets its surface; normal in n.
float4 SylvaView(Texture2D albedo, Texture2D normal, SamplerState s, float views, float3 center,
                 float radius, float2 view, float3 p, float3 ray, out float3 n) {
    float3 direction = SylvaDecode(view / (views - 1.0) * 2.0 - 1.0);
    float3 right, up;
    SylvaFrame(direction, right, up);
    float3 from_center = p - center;
    float facing = min(dot(ray, direction), -1e-4);
    float depth = 0.0;
    float2 uv = 0.0;
    float4 nd = 0.5;
    [unroll] for (int step = 0; step <= 2; ++step) {
        float3 hit = from_center + ray * ((depth - dot(from_center, direction)) / facing);
        float2 tile = float2(dot(hit, right), -dot(hit, up)) / radius * 0.5 + 0.5;
        if (any(tile < 0.0) || any(tile > 1.0)) {
            n = 0.0;
            return 0.0;
        }
        uv = (view + tile) / views;
        uv.y = 1.0 - uv.y;  // Unity: v = 0 at the bottom row
        nd = normal.SampleLevel(s, uv, 0.0);
        depth = (nd.a - 0.5) * 2.0 * radius;
    }
    n = nd.rgb * 2.0 - 1.0;
    return albedo.Sample(s, uv);
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
    float4 c = w.x * SylvaView(albedo, normal, s, views, center, radius, a, p, ray, na) +
               w.y * SylvaView(albedo, normal, s, views, center, radius, cell + float2(1, 0), p, ray, nb) +
               w.z * SylvaView(albedo, normal, s, views, center, radius, cell + float2(0, 1), p, ray, nc);
    float3 n = w.x * na + w.y * nb + w.z * nc;
    color = c.rgb;
    alpha = min(c.a * 1.4, 1.0);  // the layout's coverage_gain, as the reference
    normal_os = SylvaMirror(dot(n, n) > 0.0 ? normalize(n) : float3(0, 1, 0), mirror_x);
}
