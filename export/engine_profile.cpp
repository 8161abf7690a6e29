#include "export/engine_profile.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace sylva {
namespace {

constexpr std::string_view kAllKits[] = {"godot3", "godot4", "unity", "unreal"};
constexpr std::string_view kUnityKit[] = {"unity"};
constexpr std::string_view kUnrealKit[] = {"unreal"};
constexpr std::string_view kGodotKits[] = {"godot3", "godot4"};

// The registry: one line per engine, in EngineProfile's order.
const ProfileInfo kProfiles[] = {
    {EngineProfile::Generic, "generic", "no collision, wind in COLOR_1 (wind.glsl)",
     WindChannel::Color1, false, false, false, 1.0f, kAllKits},
    {EngineProfile::Unity, "unity", "tree_collider_<i>, wind in uv2/uv3 (v pre-flipped)",
     WindChannel::TexCoord12, false, true, true, 1.0f, kUnityKit},
    {EngineProfile::Unreal, "unreal", "UCX_ hulls, wind in UV 1/2, OBJ/PLY in centimetres",
     WindChannel::TexCoord12, false, false, true, 100.0f, kUnrealKit},
    {EngineProfile::Godot, "godot", "-convcolonly hulls, wind in UV2 as floats",
     WindChannel::TexCoord12, true, false, true, 1.0f, kGodotKits},
};

}  // namespace

std::span<const ProfileInfo> engine_profiles() {
    return kProfiles;
}

const ProfileInfo& profile_info(EngineProfile profile) {
    return kProfiles[static_cast<std::size_t>(profile)];
}

std::optional<EngineProfile> profile_from_name(std::string_view name) {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const ProfileInfo& p : kProfiles)
        if (p.name == lower) return p.profile;
    return std::nullopt;
}

std::string profile_names() {
    std::string names;
    const std::size_t n = std::size(kProfiles);
    for (std::size_t i = 0; i < n; ++i)
        names += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + std::string(kProfiles[i].name);
    return names;
}

std::string collision_name(EngineProfile profile, const std::string& model, std::size_t index,
                           bool chain) {
    switch (profile) {
        case EngineProfile::Unreal: {
            char number[24];
            std::snprintf(number, sizeof number, "%02zu", index);
            return "UCX_" + model + (chain ? "_LOD0_" : "_") + number;
        }
        case EngineProfile::Godot:
            return model + "_collision_" + std::to_string(index) + "-convcolonly";
        case EngineProfile::Unity:
        case EngineProfile::Generic:
            break;
    }
    return model + "_collider_" + std::to_string(index);
}

}  // namespace sylva
