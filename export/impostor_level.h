// The far levels of an export (docs/impostors.md): the finished tree's level 0 baked by
// impostor/ into an octahedral impostor (one quad, an albedo and a normal atlas, its layout
// in the node's glTF extras) and/or a billboard of crossed quads, appended to a model as
// its last levels in the form every writer takes: meshes with UVs and PartTextures.
#pragma once

#include <filesystem>
#include <string>

#include "export/export_tree.h"
#include "impostor/impostor_files.h"

namespace sylva {

// Bakes model.levels[0] (bake_parts()) as options.impostor says and appends a level per
// far level: `billboard` (crossed quads) before `impostor` (one quad). Needs a kind other
// than None and a level 0. The textures are PNG (sRGB albedo, linear normals, dilated).
void add_far_levels(EngineModel& model, const ExportOptions& options);

// The layout JSON (impostor/impostor_files.h) of the model's far levels, the images named
// as the format writes them for a model at `path`: a glb's image names (embedded), or the
// PNG files beside it (texture_file_name()).
std::string far_levels_layout(const EngineModel& model, const std::filesystem::path& path,
                              const ExportFormat* format);

// The image names of the layout for a model at `path`: glb image names when `embedded`.
ImpostorImageNames impostor_image_names(const std::filesystem::path& path, bool embedded);

}  // namespace sylva
