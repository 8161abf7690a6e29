// What every exporter (OBJ + MTL, glTF binary, PLY) agrees on: the shading, a few
// per-format choices, the engine profile and what write_tree() adds for engines, and the
// shape of a format's entry in the registry (export/export.h). glTF and OBJ are Y up, PLY
// Z up; units are metres (OBJ and PLY in centimetres for the unreal profile).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "export/engine_profile.h"
#include "export/named_mesh.h"
#include "export/wind_motion.h"

namespace sylva {

class FileSet;

enum class Shading {
    Flat,    // faceted: one normal per triangle (glTF splits vertices per face)
    Smooth,  // one normal per vertex, vertices shared except across creases (mesh_normals.h)
};

// What write_tree() (export/export_tree.h) puts on the parts for engines.
struct EngineSettings {
    bool uvs = true;   // bark along the branches, leaf cards, a box projection on crowns
    bool wind = true;  // the per-vertex wind data
    // The wind the engine kits' shaders play it in (the tree's wind parameters,
    // wind_motion()): glb material extras and FBX material user properties carry it.
    WindMotion wind_motion{};
    // Collision shapes (trunk hull, crown piece hulls); unset: the profile's default.
    std::optional<bool> collision = std::nullopt;
    // 0 (flat colours) to 1: a seeded per-branch, per-crown-piece and per-leaf tint.
    float color_variation = 0.0f;
    // 0 (none) to 1: darkening toward the middle of the crown, like ambient occlusion.
    float crown_occlusion = 0.0f;
    std::uint64_t seed = 1;  // of the colour variation and the wind phases
    // UVs into a palette texture of colour swatches instead (export/palette.h).
    bool palette = false;
};

// The far levels write_tree() appends after the tree's own (impostor/, docs/impostors.md):
// an octahedral impostor (one quad, an atlas of views, a shader in the engine kits), a
// billboard of crossed quads any importer shows, or both (billboard first).
enum class ImpostorKind { None, Octahedral, Billboard, Both };
struct ImpostorOptions {
    ImpostorKind kind = ImpostorKind::None;
    int size = 0;             // atlas side in pixels; 0: per tree (impostor/impostor_layout.h)
    int views = 8;            // N x N views
    bool depth = true;        // depth in the normal atlas's alpha (the shaders' parallax)
    int billboard_quads = 3;  // 2 or 3
};

struct ExportOptions {
    Shading shading = Shading::Flat;
    // Smooth shading only: faces meeting at more than this many degrees stay sharp.
    float crease_degrees = 60.0f;
    // PLY only: binary little-endian (compact, exact) or ASCII (readable).
    bool ply_binary = true;
    // The model's name: glTF root node, and with _LOD0.. the level nodes of a LOD chain.
    std::string model_name = "tree";
    // Material names become `<prefix>_<part>` (write_tree() puts it on the parts; empty:
    // the part names). material_prefix() (export/export_tree.h) makes one per tree, so
    // trees imported into one engine project do not share materials by name.
    std::string material_prefix{};
    // The engine whose conventions the export follows (export/engine_profile.h).
    EngineProfile profile = EngineProfile::Generic;
    EngineSettings engine{};  // read by write_tree(), not by the writers
    // write_tree() also writes the profile's engine import kit here (export/engine_kit.h),
    // as one transaction with the model; empty: no kit.
    std::filesystem::path engine_kit{};
    // The palette texture's PNG when the parts' UVs point into it (write_tree() sets it
    // with engine.palette): embedded in a glb, `<stem>_palette.png` beside an OBJ.
    std::vector<std::uint8_t> palette_png{};
    ImpostorOptions impostor{};  // read by write_tree(), not by the writers
    // Files beside the model, `<stem><suffix>` (the impostor's layout JSON), written and
    // committed with it by write_lod_chain(); write_tree() fills it.
    struct Sidecar {
        std::string suffix;
        std::string text;
    };
    std::vector<Sidecar> sidecars{};
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

// `<stem>_<texture>_<map>.png` beside `path` (map: albedo, normal): where a writer that
// does not embed a part's textures (PartTextures) puts them.
std::filesystem::path texture_file_name(const std::filesystem::path& path, std::string_view texture,
                                        std::string_view map);

}  // namespace sylva
