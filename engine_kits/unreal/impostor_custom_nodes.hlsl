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
float hitWeight = 0.0;
float atlasWidth, atlasHeight;
Normal.GetDimensions(atlasWidth, atlasHeight);
float tilePx = atlasWidth / Views;
// The march through each view's depth (the layout's relief_steps 64, relief_refinements 3,
// surface_texels 5): a point is on the surface where its texel (read unfiltered, at its
// centre) is covered and the point lies from `band` behind the texel's depth to that depth.
float stepLength = 2.0 * Radius / 64.0;
float band = 5.0 * 2.0 * Radius / tilePx + stepLength;
for (int k = 0; k < 3; ++k) {
    float2 s = views[k] / last * 2.0 - 1.0;
    float2 pp = float2(s.x + s.y, s.x - s.y) * 0.5;
    float3 d = normalize(float3(pp.x, max(1.0 - abs(pp.x) - abs(pp.y), 0.0), pp.y));
    float3 rr = cross(float3(0, 1, 0), d);
    float3 right = dot(rr, rr) > 1e-12 ? normalize(rr) : float3(1, 0, 0);
    float3 up = cross(d, right);
    float3 fromCenter = p - Center;
    // The hit is read at the mip level of the quad's own footprint: the march branches.
    float2 onPlane = (views[k] + float2(dot(fromCenter, right), -dot(fromCenter, up)) / Radius *
                      0.5 + 0.5) / Views;
    float2 du = ddx(onPlane);
    float2 dv = ddy(onPlane);
    if (weights[k] <= 0.0 || dot(ray, d) >= -1e-4) continue;
    // tries 0..64: the march, from Radius toward the camera to Radius behind the centre;
    // then 3 halvings between the last miss and the first hit; then the hit itself.
    float front = Radius, back = Radius, t = Radius;
    bool found = false;
    int halvings = 0;
    float2 uv = 0;
    [loop] for (int i = 0; i <= 64 + 4; ++i) {
        if (!found) t = Radius - stepLength * i;
        else if (halvings < 3) t = 0.5 * (front + back);
        else t = back;
        float3 q = fromCenter - ray * t;
        float2 tile = float2(dot(q, right), -dot(q, up)) / Radius * 0.5 + 0.5;
        uv = (views[k] + tile) / Views;  // Unreal: v = 0 at the image's top row
        bool onSurface = false;
        if (all(tile >= 0.0) && all(tile < 1.0)) {
            float2 texel = (views[k] * tilePx + floor(tile * tilePx) + 0.5) / (Views * tilePx);
            float depth = (Texture2DSampleLevel(Normal, NormalSampler, texel, 0).a - 0.5) * 2.0 * Radius;
            float along = dot(q, d);
            onSurface = Texture2DSampleLevel(Albedo, AlbedoSampler, texel, 0).a > 0.0 &&
                        along <= depth && along >= depth - band;
        }
        if (found && halvings >= 3) break;  // uv is the hit's
        if (!found) {
            if (i > 64) break;  // missed
            if (!onSurface) continue;
            found = true;
            front = t + stepLength;
            back = t;
            halvings = i > 0 ? 0 : 3;
        } else {
            if (onSurface) back = t; else front = t;
            ++halvings;
        }
    }
    if (found && halvings >= 3) {
        color += weights[k] * Albedo.SampleGrad(AlbedoSampler, uv, du, dv);
        n += weights[k] * (Normal.SampleGrad(NormalSampler, uv, du, dv).rgb * 2.0 - 1.0);
        hitWeight += weights[k];
    }
}
// A view the ray misses adds no coverage; colour averages the views it hits.
color.rgb /= max(hitWeight, 1e-6);
n = dot(n, n) > 0.0 ? normalize(n) : float3(0, 1, 0);
NormalLocal = float3(n.x, n.z, n.y);  // back to Unreal's axes (a direction: no scale)
color.a = min(color.a * 1.4, 1.0);  // the layout's coverage_gain, as the reference
return color;
