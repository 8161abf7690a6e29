// The far levels as plain meshes with UVs, a form every writer takes (a mesh, UVs per
// triangle corner with v up the image, and the texture they point into):
// - the octahedral impostor: one quad facing +z through the bounds' centre, 2r on a side,
//   its UVs on the atlas tile of the +z view, so an importer without the shader shows that
//   view; the shader (docs/impostors.md) turns it to the camera and computes its own UVs;
// - the billboard: one quad per billboard view, crossed about the vertical axis through
//   the centre, each on its tile (seen from behind: the mirror image, as crossed cards are).
// Pure functions, thread-safe.
#pragma once

#include <array>
#include <glm/vec2.hpp>
#include <vector>

#include "core/mesh.h"
#include "impostor/impostor_bake.h"

namespace sylva {

struct TexturedMesh {
    Mesh mesh;
    std::vector<std::array<glm::vec2, 3>> uv;  // per triangle corner, v up the image
};

TexturedMesh impostor_quad(const ImpostorAtlas& atlas);
TexturedMesh billboard_quads(const BillboardTexture& billboard);

// The atlas view (i, j) whose direction is +z: the corner (N - 1, 0).
glm::ivec2 front_view(int views);

}  // namespace sylva
