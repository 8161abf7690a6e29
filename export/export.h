// The export formats Sylva writes, found by name or by a file's extension, and one entry
// that writes a model or a LOD chain in any of them. Adding a format: a writer file in
// export/ that defines an ExportFormat, and one line in the table in export.cpp.
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "export/export_options.h"

namespace sylva {

// Every format: obj, glb, ply, fbx.
std::span<const ExportFormat* const> export_formats();
// Their extensions (".obj"), in the same order, for help and messages.
std::span<const std::string_view> format_extensions();

// By extension, any letter case (".OBJ" is obj); nullptr for none of them.
const ExportFormat* format_from_extension(const std::filesystem::path& path);
// By name, any letter case ("GLB"), for a --format flag; nullptr otherwise.
const ExportFormat* format_from_name(std::string_view name);

// Writes the parts to `path` in `format`, or in the format its extension names. Returns
// every file written (an OBJ comes with its .mtl). Throws InputError when no format is
// given and the extension is none of the known ones, IoError (naming the path) when a file
// cannot be written. All or nothing (core/file_set.h): every file of the model is staged
// beside its target and moved into place only when all were written; on failure no new
// file is left and existing ones are untouched. A symlink at `path` is written through
// (the file it points to is replaced, siblings go beside that file); a directory, device
// or FIFO there is refused with IoError.
std::vector<std::filesystem::path> write_model(const std::filesystem::path& path,
                                               const ModelParts& parts,
                                               const ExportOptions& options = {},
                                               const ExportFormat* format = nullptr);

// levels[0] is the finest. .glb and .fbx: one file with a node per level (write_glb_lods,
// an FBX LOD group); .obj and
// .ply: one file per level as lod_file_names() says (OBJ: plus one shared `<stem>.mtl`),
// each level's parts named as given. Returns the files written. Errors and all-or-nothing
// as write_model(): a level that fails leaves no file of any level.
// `extra`, when given, adds more files to the same set before it is committed (write_tree()'s
// engine kit), so they land together with the model or not at all.
std::vector<std::filesystem::path> write_lod_chain(const std::filesystem::path& path,
                                                   const std::vector<ModelParts>& levels,
                                                   const ExportOptions& options = {},
                                                   const ExportFormat* format = nullptr,
                                                   const std::function<void(FileSet&)>& extra = {});

// "obj, glb, ply or fbx": every format's name, for messages.
std::string format_names();

}  // namespace sylva
