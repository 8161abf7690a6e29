// Wavefront OBJ export: one group per part, Y up, meters. Written atomically.
//
// Two flavours: write_obj() writes bare geometry (positions and triangles), and
// write_obj_with_mtl() adds normals (flat or smooth) and a material library beside the
// file (`tree.obj` -> `tree.mtl`) with one material per part, named like the part, whose
// Kd is the part's colour. A part's attributes add `vt` (indexed apart from `v`, so seams
// split no vertex) and, with a tint, `v x y z r g b`; collision parts are bare `o` groups
// without material; a palette is written beside as `<stem>_palette.png` (map_Kd).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh.h"
#include "export/export_options.h"
#include "export/named_mesh.h"

namespace sylva {

void write_obj(std::ostream& out, const std::vector<NamedMesh>& parts);

// Throws IoError naming the path when it cannot be written; never leaves a partial file.
void write_obj(const std::filesystem::path& path, const std::vector<NamedMesh>& parts);

// The OBJ text that goes with an MTL file called `mtl_file_name` (written beside it):
// per part `o` and `g` with the part's name + `group_suffix` (`_LOD<i>` in a chain, so
// engines group the levels), `usemtl` with the part's name (materials are shared by the
// levels), `v`, `vn` and `f v//vn` lines. Empty parts are left out.
// Materials are named as material_name() (export/named_mesh.h) says.
void write_obj_with_mtl(std::ostream& out, const std::vector<NamedMesh>& parts,
                        const ExportOptions& options, std::string_view mtl_file_name,
                        std::string_view group_suffix = {});

// One `newmtl` per non-empty part: Kd = its colour (linear RGB, as glTF's
// baseColorFactor), no specular. With a `texture` (the palette, export/palette.h): Kd 1 1 1
// and `map_Kd texture`. A part with its own textures (PartTextures) gets Kd 1 1 1, map_Kd
// and map_d on its albedo and `norm` on its normal map, named as texture_file_name() says
// for a model at `model_path`.
void write_mtl(std::ostream& out, const std::vector<NamedMesh>& parts,
               std::string_view texture = {}, const std::filesystem::path& model_path = {});

// Writes `path` and its material library (`path` with the extension .mtl) as one
// transaction (core/file_set.h): both or neither. Returns both paths. Throws IoError naming
// the path that failed; an existing .obj and .mtl then stay as they were.
std::vector<std::filesystem::path> write_obj_with_mtl(const std::filesystem::path& path,
                                                      const std::vector<NamedMesh>& parts,
                                                      const ExportOptions& options = {});

// The registry entry (export/export.h): one level writes `path` and its .mtl; a LOD chain
// writes `<stem>_LOD<i>.obj` per level, groups `<part>_LOD<i>`, and one `<stem>.mtl` with
// one material per part name that all levels share.
extern const ExportFormat obj_format;

}  // namespace sylva
