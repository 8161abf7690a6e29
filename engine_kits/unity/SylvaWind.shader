// Sylva wind for Unity's built-in render pipeline: a surface shader that sways a tree
// exported with `sylva export --profile unity`, reading the mesh's uv2 = (sway, flex) and
// uv3 = (phase, flutter) (TEXCOORD_1/2 of the glb, UV sets 1/2 of the FBX). The motion is
// docs/wind.glsl's, in the tree's wind (_WindStrength, _WindDirection, _WindGustFrequency,
// _WindFlutter: SylvaTreePostprocessor.cs sets them from the export); the colour is _Color
// times the vertex colour (the tint; white without one). Both faces are drawn (leaves are cards). For URP or HDRP, port the vertex offset of
// docs/wind.glsl to a Shader Graph (Position node, UV1/UV2 inputs).
Shader "Sylva/Wind"
{
    Properties
    {
        _Color ("Color", Color) = (0.3, 0.55, 0.2, 1)
        _WindDirection ("Wind direction (x, z)", Vector) = (1, 0, 0, 0)
        _WindStrength ("Wind strength (metres at the top)", Float) = 0.3
        _WindGustFrequency ("Gusts per second", Float) = 0.15
        _WindFlutter ("Leaf flutter (share of strength)", Float) = 0.1
    }
    SubShader
    {
        Tags { "RenderType" = "Opaque" }
        Cull Off
        CGPROGRAM
        #pragma surface surf Lambert vertex:vert addshadow
        #pragma target 3.0

        fixed4 _Color;
        float4 _WindDirection;
        float _WindStrength;
        float _WindGustFrequency;
        float _WindFlutter;

        struct Input
        {
            float4 color : COLOR;
        };

        // Hoskins (2014), "Hash without Sine": [0, 1) from a float.
        float SylvaHash(float p)
        {
            p = frac(p * 0.1031);
            p *= p + 33.33;
            p *= p + p;
            return frac(p);
        }

        // How hard the wind blows at time t, in [0.5, 1.5] (docs/wind.glsl's sylva_gust).
        float SylvaGust(float t, float frequency)
        {
            float x = t * frequency;
            float i = floor(x), f = x - i;
            float g0 = 2.0 * SylvaHash(i) - 1.0, g1 = 2.0 * SylvaHash(i + 1.0) - 1.0;
            float u = f * f * (3.0 - 2.0 * f);
            return 1.0 + lerp(g0 * f, g1 * (f - 1.0), u);
        }

        void vert(inout appdata_full v)
        {
            float sway = v.texcoord1.x, flex = v.texcoord1.y;
            float phase = 6.2831853 * v.texcoord2.x, flutter = v.texcoord2.y;
            float t = _Time.y;
            float3 p = v.vertex.xyz;
            float3 along = normalize(float3(_WindDirection.x, 0, _WindDirection.y) + 1e-6);
            float lean = _WindStrength * SylvaGust(t, _WindGustFrequency);
            float3 offset = along * lean * sway;
            offset += lean * 0.35 * flex * sin(2.1 * t + phase) * (along + float3(0, 0.3, 0));
            offset += lean * _WindFlutter * flutter * sin(11.0 * t + 3.0 * phase + p.x + p.z) *
                      float3(0.5 * along.x, 1.0, 0.5 * along.z);
            v.vertex.xyz += offset;
        }

        void surf(Input IN, inout SurfaceOutput o)
        {
            o.Albedo = _Color.rgb * IN.color.rgb;
        }
        ENDCG
    }
    FallBack "Diffuse"
}
