// Sylva octahedral impostor, Built-in Render Pipeline surface shader (docs/impostors.md).
// Put it on the `impostor` mesh of an export with --impostor; Albedo and Normal are the
// impostor_albedo (sRGB) and impostor_normal (linear: sRGB off, not a normal map) textures,
// both with mipmaps, Clamp, Bilinear or Trilinear; Views, Center and Radius are the
// layout's (the node's glTF extras, or OUT_impostor.json). For URP/HDRP use the same
// functions from a Shader Graph Custom Function node (impostor_SylvaImpostor.hlsl).
Shader "Sylva/Octahedral Impostor" {
    Properties {
        _Albedo ("Albedo atlas", 2D) = "white" {}
        _Normal ("Normal + depth atlas", 2D) = "gray" {}
        _Views ("Views (N of N x N)", Float) = 8
        _Center ("Center (layout)", Vector) = (0, 0, 0, 0)
        _Radius ("Radius (layout)", Float) = 1
        _MirrorX ("Mirror X (1 for glTF/FBX imports)", Float) = 1
    }
    SubShader {
        Tags { "Queue" = "AlphaTest" "RenderType" = "TransparentCutout" "DisableBatching" = "True" }
        Cull Off
        CGPROGRAM
        #pragma surface surf Standard vertex:vert addshadow
        #pragma target 3.5
        #include "impostor_SylvaImpostor.hlsl"

        Texture2D _Albedo;
        Texture2D _Normal;
        SamplerState sampler_Albedo;
        float _Views, _Radius, _MirrorX;
        float4 _Center;

        struct Input {
            float3 quad_os;
        };

        void vert(inout appdata_full v, out Input o) {
            UNITY_INITIALIZE_OUTPUT(Input, o);
            float3 camera_os = mul(unity_WorldToObject, float4(_WorldSpaceCameraPos, 1)).xyz;
            float3 p;
            SylvaImpostorVertex_float(v.vertex.xyz, camera_os, _Views, _Center.xyz, _Radius,
                                      _MirrorX, p);
            v.vertex.xyz = p;
            v.normal = normalize(camera_os - p);
            v.tangent = float4(normalize(cross(float3(0, 1, 0), v.normal) + 1e-6), 1);
            o.quad_os = p;
        }

        void surf(Input i, inout SurfaceOutputStandard o) {
            float3 camera_os = mul(unity_WorldToObject, float4(_WorldSpaceCameraPos, 1)).xyz;
            float3 color, normal_os;
            float alpha;
            SylvaImpostorFragment_float(_Albedo, _Normal, sampler_Albedo, i.quad_os, camera_os,
                                        _Views, _Center.xyz, _Radius, _MirrorX, color, alpha,
                                        normal_os);
            clip(alpha - 0.5);
            o.Albedo = color;
            o.Alpha = 1;
            o.Smoothness = 0.1;
            // The surface shader wants a tangent-space normal: the quad's frame turns with
            // the camera, so express the object-space normal in it.
            float3 n = normalize(camera_os - i.quad_os);
            float3 t = normalize(cross(float3(0, 1, 0), n) + 1e-6);
            float3 b = cross(n, t);
            o.Normal = normalize(float3(dot(normal_os, t), dot(normal_os, b), dot(normal_os, n)));
        }
        ENDCG
    }
    FallBack "Legacy Shaders/Transparent/Cutout/VertexLit"
}
