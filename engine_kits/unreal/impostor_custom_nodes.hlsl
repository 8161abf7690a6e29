// Sylva octahedral impostor for Unreal Engine (docs/impostors.md; a port of
// docs/impostor.glsl): the text of two Custom material-expression nodes for a material
// function "MF_SylvaImpostor". Material: Blend Mode Masked, Two Sided, Tangent Space Normal
// off (the normal output is in world space).
//
// Axes: Unreal is Z up, left-handed, centimetres; the glTF and FBX importers turn the
// export's Y-up metres into that. The code maps a local Unreal vector to the
// export's axes for the common conversion: Unreal (x, y, z) = export (x, z, y) * 100 (the
// .xzy swizzles and the factors 0.01 and 100 below); if your import rotates differently (a
// forward axis option), change those lines. Custom nodes are function bodies: no helper
// functions, everything inline. Center and
// Radius are the layout's (metres, the export's axes).
//
// ---- Node 1: "SylvaImpostorOffset" (World Position Offset) --------------------------
// Inputs: LocalPosition (float3, the vertex: TransformPosition Absolute World -> Local of
//         Absolute World Position, excluding offsets), CameraLocal (float3, the camera:
//         Camera Position transformed to Local), Views (scalar), Center (float3),
//         Radius (scalar). Output (float3): the local offset; transform it Local -> World
//         (vector) and plug it into World Position Offset.
// Code:
float3 p = LocalPosition.xzy * 0.01;  // to the export's axes
float3 cam = CameraLocal.xzy * 0.01;
float3 d = normalize(cam - Center);
float3 r = cross(float3(0, 1, 0), d);
float3 right = dot(r, r) > 1e-12 ? normalize(r) : float3(1, 0, 0);
float3 up = cross(d, right);
float2 corner = (p.xy - Center.xy) / Radius;
float3 turned = Center + Radius * (corner.x * right + corner.y * up);
return turned.xzy * 100.0 - LocalPosition;

// ---- Node 2: "SylvaImpostorSample" (Base Color, Opacity Mask, Normal) ----------------
// Inputs: LocalPosition (float3, the pixel: TransformPosition Absolute World -> Local of
//         Absolute World Position), CameraLocal (float3), Albedo (Texture Object: the
//         impostor_albedo texture, sRGB, Clamp), Normal (Texture Object: impostor_normal,
//         sRGB off, compression "Masks" or "VectorDisplacementmap", not Normalmap, Clamp),
//         Views, Center, Radius as above.
// Output (float4): rgb = base colour, a = opacity mask (clip at 0.5). Additional output
// "NormalLocal" (float3): the normal in local space; transform Local -> World (vector) into
// Normal.
// Code (Unreal pastes it into a function body; Custom nodes allow loops and locals):
float3 p = LocalPosition.xzy * 0.01;  // to the export's axes
float3 cam = CameraLocal.xzy * 0.01;
float3 toCam = normalize(cam - Center);
toCam.y = max(toCam.y, 0.0);
float2 q = toCam.xz / (abs(toCam.x) + toCam.y + abs(toCam.z));
float last = Views - 1.0;
float2 grid = (float2(q.x + q.y, q.x - q.y) * 0.5 + 0.5) * last;
float2 cell = clamp(floor(grid), 0.0, last - 1.0);
float2 f = saturate(grid - cell);
bool lower = f.x + f.y <= 1.0;
float2 views[3] = {lower ? cell : cell + 1.0, cell + float2(1, 0), cell + float2(0, 1)};
float weights[3] = {lower ? 1.0 - f.x - f.y : f.x + f.y - 1.0, lower ? f.x : 1.0 - f.y,
                    lower ? f.y : 1.0 - f.x};
float3 ray = normalize(p - cam);
float4 color = 0;
float3 n = 0;
for (int k = 0; k < 3; ++k) {
    float2 s = views[k] / last * 2.0 - 1.0;
    float2 pp = float2(s.x + s.y, s.x - s.y) * 0.5;
    float3 d = normalize(float3(pp.x, max(1.0 - abs(pp.x) - abs(pp.y), 0.0), pp.y));
    float3 rr = cross(float3(0, 1, 0), d);
    float3 right = dot(rr, rr) > 1e-12 ? normalize(rr) : float3(1, 0, 0);
    float3 up = cross(d, right);
    float3 fromCenter = p - Center;
    float facing = min(dot(ray, d), -1e-4);
    float depth = 0.0;
    float2 uv = 0;
    float4 nd = 0.5;
    bool inside = true;
    for (int step = 0; step <= 2; ++step) {
        float3 hit = fromCenter + ray * ((depth - dot(fromCenter, d)) / facing);
        float2 tile = float2(dot(hit, right), -dot(hit, up)) / Radius * 0.5 + 0.5;
        inside = inside && all(tile >= 0.0) && all(tile <= 1.0);
        uv = (views[k] + saturate(tile)) / Views;  // Unreal: v = 0 at the image's top row
        nd = Texture2DSampleLevel(Normal, NormalSampler, uv, 0);
        depth = (nd.a - 0.5) * 2.0 * Radius;
    }
    if (inside) {
        color += weights[k] * Texture2DSample(Albedo, AlbedoSampler, uv);
        n += weights[k] * (nd.rgb * 2.0 - 1.0);
    }
}
n = dot(n, n) > 0.0 ? normalize(n) : float3(0, 1, 0);
NormalLocal = float3(n.x, n.z, n.y);  // back to Unreal's axes (a direction: no scale)
color.a = min(color.a * 1.4, 1.0);  // the layout's coverage_gain, as the reference
return color;
