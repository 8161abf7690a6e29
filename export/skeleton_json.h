// skeleton.json (docs/skeleton-json.md): the skeleton with the parameters in effect, for
// other tools and for checking. Positions and radii are exactly those the SDF stage uses.
#pragma once

#include <filesystem>
#include <string>

#include "core/skeleton.h"
#include "core/tree_params.h"

namespace sylva {

std::string skeleton_json(const Skeleton& skeleton, const TreeParams& params);

// Throws IoError naming the path; never leaves a partial file.
void write_skeleton_json(const std::filesystem::path& path, const Skeleton& skeleton,
                         const TreeParams& params);

}  // namespace sylva
