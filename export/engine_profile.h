// Per-engine export conventions (`--profile generic|unity|unreal|godot`): how collision
// meshes are named, which glTF channel carries the wind data, whether collision is written
// by default, and the unit of OBJ files. docs/engines.md's profile table says the same.
#pragma once

#include <optional>
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
    std::string_view name;  // what --profile takes
    WindChannel wind;
    bool collision_by_default;
    // OBJ and PLY are unitless: Unreal reads them as centimetres, everyone else as metres.
    float unitless_scale;
};

const ProfileInfo& profile_info(EngineProfile profile);
// By name, any letter case; nullopt otherwise.
std::optional<EngineProfile> profile_from_name(std::string_view name);
// "generic, unity, unreal or godot", for messages.
std::string profile_names();

// The name of collision shape `index` of a model (0 is the trunk, 1.. the crown pieces),
// as the engine's importer wants it: Unreal `UCX_<model>_00` (attached to the mesh named
// <model>), Godot `<model>_collision_0-convcolonly` (a convex static body), Unity and
// generic `<model>_collider_0` (a mesh to give a MeshCollider).
std::string collision_name(EngineProfile profile, const std::string& model, std::size_t index);

}  // namespace sylva
