// Per-engine export conventions (`--profile generic|unity|unreal|godot`): how collision
// meshes are named, how the wind data goes into a glb, whether collision is written by
// default, the unit of OBJ and PLY files and which engine import kit (engine_kits/) goes
// with the export. One table (engine_profile.cpp) is the registry: --profile's parsing and
// help, the studio's combo and docs/engines.md's profile table follow it.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace sylva {

enum class EngineProfile { Generic, Unity, Unreal, Godot };

// Where the four wind values (export/part_attributes.h) go in a glb.
enum class WindChannel {
    Color1,      // COLOR_1, one vec4: what a custom renderer reads most easily
    TexCoord12,  // TEXCOORD_1 = (sway, flex), TEXCOORD_2 = (phase, flutter): the UV
                 // channels every engine imports (Unity uv1/uv2, Unreal UV 1/2, Godot UV2)
};

struct ProfileInfo {
    EngineProfile profile;
    std::string_view name;     // what --profile takes
    std::string_view summary;  // one line for help texts and tooltips
    WindChannel wind;
    // TEXCOORD_1/2 as 32-bit floats instead of normalized 16-bit integers: Godot 3.2.3
    // ignores glTF's `normalized` flag and reads the integers as 0..65535.
    bool wind_as_floats;
    // TEXCOORD_1/2 written as (x, 1 - y): Unity's glTF importers (glTFast, UnityGLTF) flip v
    // on every UV set, so the wind arrives as written in the other profiles.
    bool wind_v_flipped;
    bool collision_by_default;
    // OBJ and PLY are unitless: Unreal reads them as centimetres, everyone else as metres.
    float unitless_scale;
    // The engine_kits/ folders that --engine-kit copies for this profile.
    std::span<const std::string_view> kits;
};

// The registry, in the order help texts and the studio list them.
std::span<const ProfileInfo> engine_profiles();
const ProfileInfo& profile_info(EngineProfile profile);
// By name, any letter case; nullopt otherwise.
std::optional<EngineProfile> profile_from_name(std::string_view name);
// "generic, unity, unreal or godot", for messages.
std::string profile_names();

// The name of collision shape `index` of a model (0 is the trunk, 1.. the crown pieces),
// as the engine's importer wants it: Unreal `UCX_<mesh>_00`, where the mesh is `<model>`, or
// `<model>_LOD0` in a LOD chain (`chain`): the FBX mesh of the finest level, which Unreal
// attaches the hull to; Godot `<model>_collision_0-convcolonly` (a convex static body);
// Unity and generic `<model>_collider_0` (a mesh to give a MeshCollider).
std::string collision_name(EngineProfile profile, const std::string& model, std::size_t index,
                           bool chain = false);

}  // namespace sylva
