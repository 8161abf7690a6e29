// What every exporter (OBJ + MTL, glTF binary, PLY) agrees on: the shading, a few
// per-format choices, and the shape of a format's entry in the registry (export/export.h).
// Y is up and units are meters in all of them.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "export/named_mesh.h"

namespace sylva {

class FileSet;

enum class Shading {
    Flat,    // faceted: one normal per triangle (glTF splits vertices per face)
    Smooth,  // one normal per vertex, vertices shared except across creases (mesh_normals.h)
};

struct ExportOptions {
    Shading shading = Shading::Flat;
    // Smooth shading only: faces meeting at more than this many degrees stay sharp.
    float crease_degrees = 60.0f;
    // PLY only: binary little-endian (compact, exact) or ASCII (readable).
    bool ply_binary = true;
    // The model's name: glTF root node, and with _LOD0.. the level nodes of a LOD chain.
    std::string model_name = "tree";
};

// One level of detail: the parts of a model.
using ModelParts = std::vector<NamedMesh>;

// A file format. Each writer defines one (obj_format in obj_writer.h, ...) and
// export/export.cpp lists it.
struct ExportFormat {
    std::string_view name;       // what --format takes: "obj"
    std::string_view extension;  // with the dot, lower case: ".obj"
    // Adds the files of `levels` at `path` to `files` (core/file_set.h), which the registry
    // commits once all were written: one level is a plain model, more are a LOD chain
    // (finest first), in one file or one file per level (lod_file_names()) as the format
    // does it, siblings (an .mtl) beside `path`. Throws IoError naming the path.
    void (*write)(FileSet& files, const std::filesystem::path& path,
                  const std::vector<ModelParts>& levels, const ExportOptions& options);
};

// `<stem>_LOD<i><ext>` beside `path` for i in [0, levels): the files of a chain written one
// file per level.
std::vector<std::filesystem::path> lod_file_names(const std::filesystem::path& path,
                                                  std::size_t levels);

}  // namespace sylva
