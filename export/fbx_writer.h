// Binary FBX 7.4 export (`--format fbx`), the way Unity's and Unreal's FBX importers read a
// model: Y up, metres (UnitScaleFactor 100: the file says centimetres are 1/100 of its unit,
// so every engine converts), one Mesh model per level with one geometry in which each part
// (trunk, crown, leaves) is a material of its own, so a level is one mesh with submeshes.
//
// - One level: a Mesh model named options.model_name at the root.
// - A chain: a LodGroup model named options.model_name (an FbxLODGroup node attribute with
//   thresholds at 50%, 25%, 12.5%... of the screen) whose children are the Mesh models
//   `<model_name>_LOD<i>`, finest first: what Unity turns into a LODGroup and Unreal into
//   a static mesh's LODs.
// - Collision parts: Mesh models with their own geometry (positions, flat normals, no
//   material) at the root, named as given (the unreal profile names them
//   `UCX_<level 0 mesh>_NN`, export/engine_profile.h).
//
// Per polygon corner: normals (flat or smooth as options.shading says), UV set 0 the part's
// UVs (v up, as FBX wants), UV sets 1 and 2 the wind (sway, flex) and (phase, flutter),
// colour set 0 the tint (white without one) and colour set 1 the wind (sway, flex, phase,
// flutter), the sets present on every part when any part has them (zeros or white where a
// part lacks one). Materials are Phong with the part's colour as DiffuseColor, named by
// NamedMesh::material (the part's name when empty); a palette texture is not embedded.
// Materials and Mesh models of parts with wind data carry the wind to play it in
// (wind_values(), export/wind_motion.h) as user properties.
// The bytes go through export/fbx_document.h; the same input gives the same bytes.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "export/export_options.h"
#include "export/fbx_document.h"

namespace sylva {

// The records of the file (what encode_fbx() writes): for tests that look inside.
std::vector<fbx::Node> fbx_records(const std::vector<ModelParts>& levels,
                                   const ExportOptions& options);

// levels[0] is the finest; one level is a plain model. Throws IoError when the file cannot
// be encoded (over 4 GiB).
void write_fbx(std::ostream& out, const std::vector<ModelParts>& levels,
               const ExportOptions& options = {});

// The registry entry (export/export.h): one file for a model or a whole chain.
extern const ExportFormat fbx_format;

}  // namespace sylva
