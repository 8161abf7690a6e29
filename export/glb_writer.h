// glTF 2.0 binary (.glb) export through tinygltf: one node, mesh and material per part,
// Y up, meters (glTF's own axes and unit, so no root transform). Materials are
// metallic-roughness with the part's colour as baseColorFactor; open parts (leaves) are
// double-sided. Flat shading splits vertices per triangle so every face carries its own
// normal; smooth shares them except at creases and UV seams. A part's attributes
// (export/named_mesh.h) become TEXCOORD_0 (v flipped to glTF's v down), COLOR_0 (the
// tint) and the wind in the profile's channel, number type and v direction
// (export/engine_profile.h); materials are named as material_name() says; collision parts
// are bare POSITION + indices without material, once under the root; the material of a
// part with wind data carries the wind to play it in (wind_values(), export/wind_motion.h)
// as its extras; a palette
// (ExportOptions::palette_png) is embedded as the materials' baseColorTexture. A part with
// its own textures (NamedMesh::textures: the impostor levels) gets them embedded as its
// material's baseColorTexture and normalTexture (trilinear, clamped), alphaMode MASK,
// TANGENTs from its UVs, and their extras JSON on its node.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "export/export_options.h"
#include "export/named_mesh.h"

namespace sylva {

// Scene: a root node named options.model_name with one child node per non-empty part,
// each holding a mesh of that name with one triangle primitive.
void write_glb(std::ostream& out, const std::vector<NamedMesh>& parts,
               const ExportOptions& options);

// Throws IoError naming the path; never leaves a partial file.
void write_glb(const std::filesystem::path& path, const std::vector<NamedMesh>& parts,
               const ExportOptions& options = {});

// A LOD chain in one file: the root node has a child `<model_name>_LOD<i>` per level, whose
// children are the level's parts named `<part>_LOD<i>` (the suffixes Unity, Unreal and
// Godot group into LODs). Materials are shared across levels (one per material name).
void write_glb_lods(std::ostream& out, const std::vector<std::vector<NamedMesh>>& levels,
                    const ExportOptions& options);
void write_glb_lods(const std::filesystem::path& path,
                    const std::vector<std::vector<NamedMesh>>& levels,
                    const ExportOptions& options = {});

// The registry entry (export/export.h): one level is write_glb, a chain write_glb_lods.
extern const ExportFormat glb_format;

}  // namespace sylva
