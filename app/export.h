// One entry point for every export format: the format comes from the file's extension (or
// is given), and a LOD chain goes into one .glb or one file per level.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "app/export_options.h"
#include "app/named_mesh.h"

namespace sylva {

// ".obj", ".glb", ".ply" (any letter case); nullopt otherwise.
std::optional<ExportFormat> format_from_extension(const std::filesystem::path& path);
// "obj", "glb", "ply" (for a --format flag); nullopt otherwise.
std::optional<ExportFormat> format_from_name(std::string_view name);
std::string_view format_extension(ExportFormat format);  // ".obj", ".glb", ".ply"

// Writes the parts to `path` in `format`, or in the format its extension names. Returns
// every file written (an OBJ comes with its .mtl). Throws InputError when no format is
// given and the extension is none of the three, IoError (naming the path) when a file
// cannot be written; never leaves a partial file.
std::vector<std::filesystem::path> write_model(const std::filesystem::path& path,
                                               const std::vector<NamedMesh>& parts,
                                               const ExportOptions& options = {},
                                               std::optional<ExportFormat> format = {});

// The files of a LOD chain of `levels` levels written to `path`: the path itself for
// .glb (one file, a node per level); otherwise `<stem>_LOD<i><ext>` per level (OBJ: plus
// one shared `<stem>.mtl`).
std::vector<std::filesystem::path> lod_file_names(const std::filesystem::path& path,
                                                  std::size_t levels, ExportFormat format);

// levels[0] is the finest. .glb: one file (see write_glb_lods); .obj and .ply: one file per
// level as lod_file_names() says, each level's parts named as given. Returns the files
// written. Errors as write_model(); files of levels already written stay when a later
// level fails.
std::vector<std::filesystem::path> write_lod_chain(
    const std::filesystem::path& path, const std::vector<std::vector<NamedMesh>>& levels,
    const ExportOptions& options = {}, std::optional<ExportFormat> format = {});

}  // namespace sylva
