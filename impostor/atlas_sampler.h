// The CPU reference of the impostor shaders (engine_kits/*/impostor_*, docs/impostors.md):
// the octahedral atlas drawn from any direction of the upper hemisphere as one quad facing
// the camera that blends the three nearest views. Each view is sampled where the camera's
// ray through the quad meets the plane that view was captured on (through the centre,
// facing the view), so the three images line up at the centre and drift apart only with
// depth. Bilinear filtering of linear colour, as a GPU samples an sRGB texture. What the
// fidelity tests compare with the tree's own rendering (view_rasterizer.h). Thread-safe.
#pragma once

#include "impostor/impostor_bake.h"

namespace sylva {

// The atlas as an orthographic camera looking along -camera.direction sees it: pixel
// (x, y) of the size x size result covers the same square as render_view()'s pixel with
// the same frame and the atlas's bounds. Alpha, colour (linear RGB) and normal (object
// space, unit; zero where alpha is 0) are the weighted sums of the three views; depth is
// 0 (the atlas's depth is not read).
ViewImage render_impostor(const ImpostorAtlas& atlas, const ViewFrame& camera, int size);

}  // namespace sylva
