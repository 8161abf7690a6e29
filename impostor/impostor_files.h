// What an export writes of an impostor besides meshes: the textures as PNG and the view
// layout as JSON (the sidecar `<stem>_impostor.json` and the glTF node's `extras`), whose
// fields docs/impostors.md describes. Deterministic bytes; thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "impostor/impostor_bake.h"

namespace sylva {

// PNG bytes of the image (libpng; 3 or 4 channels, 8 bits). sRGB or linear is the
// reader's convention: glTF reads base colour as sRGB and normal maps as linear. Throws
// std::runtime_error if libpng fails.
std::vector<std::uint8_t> encode_png(const Image8& image);

// Where the images are, as the layout names them (a file name beside the model, or a glb
// image name), empty for a level not written.
struct ImpostorImageNames {
    std::string atlas_albedo, atlas_normal;
    std::string billboard_albedo, billboard_normal;
};

// The layout as a JSON object: format "sylva-impostor" version 1, the views, tile and
// atlas size, the centre and radius every view frames, how a view's direction and camera
// follow from its tile, the images and their encodings; and the billboard's quads when
// `billboard` is given. Either may be null (left out).
std::string impostor_layout_json(const ImpostorAtlas* atlas, const BillboardTexture* billboard,
                                 const ImpostorImageNames& images);

}  // namespace sylva
