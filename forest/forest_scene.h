// One glTF binary scene for a planted forest: each unique variant's meshes are stored once
// and every tree standing somewhere refers to them. Each variant is written by the tree
// exporter (export/glb_writer.h, LOD chains included) and its meshes, accessors and
// materials merged into the scene, so the forest's trees are the bytes `sylva export` makes.
//
// Two ways to share:
// - Nodes (default): a node per tree with its position, yaw and scale, whose children are
//   the variant's part nodes (and LOD groups) pointing at the shared meshes, named after the
//   tree (`tree_00012_trunk_LOD0`: the `_LOD<i>` engines look for stays last). Every glTF 2.0
//   reader takes it (Blender 3.4 imports linked duplicates); extras on the tree node name
//   the species, the variant and the placement row.
// - Gpu: the same default scene (every reader, with or without the extension, places every
//   tree), plus a second scene `forest_gpu_instanced` using EXT_mesh_gpu_instancing (used,
//   never required): one node per variant part whose instances are
//   TRANSLATION/ROTATION/SCALE accessors, what engines draw in one call. Readers that
//   support the extension load that scene by index (glTFast, three.js, Babylon.js).
#pragma once

#include <filesystem>
#include <glm/vec3.hpp>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "export/export_options.h"

namespace sylva::forest {

enum class Instancing { Nodes, Gpu };

struct SceneVariant {
    std::string name;                // the tree group's name: "oak_v3"
    std::string material_prefix;     // materials become "<prefix>_trunk", ...: one set per species
    std::vector<ModelParts> levels;  // finest first; more than one: a LOD chain
};

struct SceneInstance {
    std::size_t variant = 0;  // index into the variants
    glm::vec3 position{0.0f};
    float yaw_degrees = 0.0f;  // about +Y
    float scale = 1.0f;        // uniform
    std::string name;          // the tree node's name (Nodes only)
};

// Throws IoError when the model cannot be serialised.
void write_forest_glb(std::ostream& out, std::span<const SceneVariant> variants,
                      std::span<const SceneInstance> instances, Instancing instancing,
                      const ExportOptions& options = {});

}  // namespace sylva::forest
