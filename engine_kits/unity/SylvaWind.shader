// Sylva wind for Unity's built-in render pipeline: a surface shader that sways a tree
// exported with `sylva export --profile unity`, reading the mesh's uv2 = (sway, flex) and
// uv3 = (phase, flutter) (TEXCOORD_1/2 of the glb, UV sets 1/2 of the FBX). The motion is
// docs/wind.glsl's; the colour is _Color times the vertex colour (the tint; white without
// one). Both faces are drawn (leaves are cards). For URP or HDRP, port the vertex offset of
// docs/wind.glsl to a Shader Graph (Position node, UV1/UV2 inputs).
Shader "Sylva/Wind"
{
    Properties
    {
        _Color ("Color", Color) = (0.3, 0.55, 0.2, 1)
        _WindDirection ("Wind direction (x, z)", Vector) = (1, 0, 0, 0)
        _WindStrength ("Wind strength (metres at the top)", Float) = 0.3
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

        struct Input
        {
            float4 color : COLOR;
        };

        void vert(inout appdata_full v)
        {
            float sway = v.texcoord1.x, flex = v.texcoord1.y;
            float phase = 6.2831853 * v.texcoord2.x, flutter = v.texcoord2.y;
            float t = _Time.y;
            float3 p = v.vertex.xyz;
            float3 along = normalize(float3(_WindDirection.x, 0, _WindDirection.y) + 1e-6);
            float gust = 0.65 + 0.35 * sin(0.9 * t) * sin(0.37 * t + 1.3);
            float3 offset = along * _WindStrength * sway * gust;
            offset += _WindStrength * 0.35 * flex * sin(2.1 * t + phase) * (along + float3(0, 0.3, 0));
            offset.y += _WindStrength * 0.1 * flutter * sin(11.0 * t + 3.0 * phase + p.x + p.z);
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
