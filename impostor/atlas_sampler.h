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

// The blended alpha is multiplied by this (at most 1) before the 0.5 alpha test, so a texel
// counts from a blended coverage of 0.36 on. The three views, lined up with one depth per
// texel, disagree by about a texel on parts a texel thin (fronds, sprays, twigs), and each
// then contributes only its weight's share of the part's coverage; the lower cut keeps those
// parts while a solid edge moves by a fraction of a texel. A single view's pixel of coverage
// 0.36 to 0.5 counts too (about half a sample of 2 x 2 more). Every shader applies it.
inline constexpr float kImpostorCoverageGain = 1.4f;

// The atlas as an orthographic camera looking along -camera.direction sees it: pixel
// (x, y) of the size x size result covers the same square as render_view()'s pixel with
// the same frame and the atlas's bounds. Alpha, colour (linear RGB) and normal (object
// space, unit; zero where alpha is 0) are the weighted sums of the three views, alpha times
// kImpostorCoverageGain (at most 1); depth is 0 (the atlas's depth is not read).
ViewImage render_impostor(const ImpostorAtlas& atlas, const ViewFrame& camera, int size);

}  // namespace sylva
