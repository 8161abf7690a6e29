// A palette texture for Quaternius-style kits: one small PNG of colour swatches (a row
// per part: trunk, crown, leaves; a column per shade, from the part's colour to 35%
// darker) and UVs that point every vertex at its swatch, so a whole forest shares one
// material. `sylva export --palette` embeds it in a glb or writes it beside an OBJ
// (`<stem>_palette.png`, the .mtl's map_Kd).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string_view>
#include <vector>

#include "core/tree_template.h"
#include "export/named_mesh.h"

namespace sylva {

constexpr int kPaletteShades = 4;
constexpr int kPaletteSwatch = 8;  // pixels per swatch side

// The PNG bytes (sRGB, kPaletteShades x 3 swatches).
std::vector<std::uint8_t> palette_png(const PartColors& colors);

// Points `attributes` of the part named `part` (trunk, crown or leaves) at its swatches:
// every corner's UV becomes the middle of the swatch whose shade is nearest the vertex's
// tint (the part's colour without one). The glb then leaves the tint out (the texture
// carries it); PLY and OBJ vertex colours keep it. v runs up the image, as
// PartAttributes' does.
void use_palette(PartAttributes& attributes, const Mesh& mesh, std::string_view part);

}  // namespace sylva
