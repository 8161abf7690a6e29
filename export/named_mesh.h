// A part of a model as the exporters see it: a name, a mesh, a colour, a material name,
// whether it is a closed solid, and optionally what engines want on top (UVs, tints, wind; a
// collision shape). The writers (OBJ, glTF, PLY) take lists of these.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "core/mesh.h"

namespace sylva {

// What a part carries besides its shape (export/part_attributes.h computes it). Any of the
// lists may be empty: the part then has none of it.
struct PartAttributes {
    // Texture coordinates per triangle corner (triangles[f][k] -> uv[f][k]): a vertex on a
    // seam has different UVs in the triangles around it, while the mesh itself stays one
    // closed surface. glTF splits such vertices, OBJ indexes `vt` apart from `v`. v runs
    // up the image as in OBJ and OpenGL (the glTF writer flips it to glTF's v down).
    std::vector<std::array<glm::vec2, 3>> uv;
    // Per vertex, multiplies the part's colour (each channel in [0, 1]): colour variation
    // and crown occlusion. Empty: the flat part colour.
    std::vector<glm::vec3> tint;
    // Per vertex, the wind data (sway, flex, phase, flutter), each in [0, 1]; see
    // docs/engines.md and docs/wind.glsl.
    std::vector<glm::vec4> wind;
};

// Images a part's colour comes from (an impostor's atlas, a billboard's views): the part's
// UVs point into them. Writers embed them (glb) or write them beside the model
// (texture_file_name() in export/export_options.h) and alpha-test the colour's alpha.
struct PartTextures {
    std::string name;                      // "impostor": glTF images impostor_albedo, ...
    std::vector<std::uint8_t> albedo_png;  // sRGB colour, straight alpha
    std::vector<std::uint8_t> normal_png;  // tangent-space normals for the UVs (linear); or empty
    float alpha_cutoff = 0.5f;
    std::string extras_json;  // a JSON object for the part's glTF node `extras`, or empty
};

struct NamedMesh {
    std::string name;  // the OBJ group and material, the glTF node, mesh and material
    const Mesh* mesh = nullptr;
    glm::vec3 color{0.7f, 0.7f, 0.7f};  // base colour, linear RGB in [0, 1]
    // Solid parts are closed and seen from outside only; open ones (leaves) get
    // double-sided materials where the format has them (glTF).
    bool closed = true;
    const PartAttributes* attributes = nullptr;  // none when null
    // A collision shape (a convex hull): written without material, colour or attributes,
    // once per model (not per LOD level), and left out of PLY.
    bool collision = false;
    // The material's name when it is not the part's: `oak_s1_trunk` for the trunk of one
    // tree, so two trees imported into one engine project keep two materials.
    std::string material{};
    const PartTextures* textures = nullptr;  // none when null: the colour is `color`
};

// The name of the part's material: NamedMesh::material, else the part's name.
inline const std::string& material_name(const NamedMesh& part) {
    return part.material.empty() ? part.name : part.material;
}

}  // namespace sylva
