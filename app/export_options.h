// What every exporter (OBJ + MTL, glTF binary, PLY) agrees on: the formats, the shading,
// and a few per-format choices. Y is up and units are meters in all of them.
#pragma once

#include <string>

namespace sylva {

enum class ExportFormat { Obj, Glb, Ply };

enum class Shading {
    Flat,    // faceted: one normal per triangle (glTF splits vertices per face)
    Smooth,  // one area-weighted normal per vertex, vertices shared
};

struct ExportOptions {
    Shading shading = Shading::Flat;
    // PLY only: binary little-endian (compact, exact) or ASCII (readable).
    bool ply_binary = true;
    // The model's name: glTF root node, and with _LOD0.. the level nodes of a LOD chain.
    std::string model_name = "tree";
};

}  // namespace sylva
