// PLY export (binary little-endian or ASCII): all parts in one vertex and face list, each
// vertex coloured with its part's colour times its tint (8-bit sRGB, as viewers expect),
// Z up (Blender's axes; PLY has no convention, and Y up lands on its back there), meters
// (centimetres for the unreal profile). Collision parts are left out.
// Vertices stay shared, so closed parts stay closed for mesh tools; smooth shading adds
// per-vertex normals (nx, ny, nz), flat shading leaves normals to the viewer.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "export/export_options.h"
#include "export/named_mesh.h"

namespace sylva {

void write_ply(std::ostream& out, const std::vector<NamedMesh>& parts,
               const ExportOptions& options);

// Throws IoError naming the path; never leaves a partial file.
void write_ply(const std::filesystem::path& path, const std::vector<NamedMesh>& parts,
               const ExportOptions& options = {});

// The registry entry (export/export.h): one level is write_ply, a chain one file per level.
extern const ExportFormat ply_format;

}  // namespace sylva
