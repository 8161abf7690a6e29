#include "export/engine_profile.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace sylva {
namespace {

const ProfileInfo kProfiles[] = {
    {EngineProfile::Generic, "generic", WindChannel::Color1, false, 1.0f},
    {EngineProfile::Unity, "unity", WindChannel::TexCoord12, true, 1.0f},
    {EngineProfile::Unreal, "unreal", WindChannel::TexCoord12, true, 100.0f},
    {EngineProfile::Godot, "godot", WindChannel::TexCoord12, true, 1.0f},
};

}  // namespace

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
    return "generic, unity, unreal or godot";
}

std::string collision_name(EngineProfile profile, const std::string& model, std::size_t index) {
    switch (profile) {
        case EngineProfile::Unreal: {
            char number[8];
            std::snprintf(number, sizeof number, "%02zu", index);
            return "UCX_" + model + "_" + number;
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
