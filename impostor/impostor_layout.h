// Choosing an octahedral impostor's layout for a tree: thin trees (sprays, fronds, twigs a
// pixel or two wide in a view) need more views than the default, because the shaders'
// three-view blend misplaces a part by up to a texel between views and a part that thin
// loses much of its area to that; the default 8 x 8 views of 128 px serve the others at a
// quarter of the cost. Thread-safe.
#pragma once

#include <span>

#include "impostor/impostor_bake.h"

namespace sylva {

// The share of an atlas's covered pixels (alpha >= 0.5) that lie in a thin part: with a
// transparent pixel (or the tile's edge) within kThinPixels pixels on both sides,
// horizontally or vertically, so in a part at most 2 kThinPixels - 1 = 3 pixels across.
// 0 for an empty atlas. One pass over the atlas (a few ms at 1024 px), on the TBB pool.
inline constexpr int kThinPixels = 2;
double thin_share(const ImpostorAtlas& atlas);

// From this thin share on, an automatic layout takes the thin layout.
inline constexpr double kThinShareLimit = 0.08;

// The automatic layout: 8 x 8 views at 1024 px, or for a thin tree 16 x 16 views at 2048 px
// (tiles of 128 px either way: more views, nearer the camera's direction, line thin parts up
// better between views than larger tiles do).
inline constexpr int kThinViews = 16;
inline constexpr int kThinSize = 2048;

// bake_impostor() with settings.size 0 (automatic) calls this: the default layout
// (settings.views at 128 px a view) is baked, and if its thin share is kThinShareLimit or
// more, the thin layout (at least kThinViews views, at least kThinSize px) replaces it. The
// atlas's `thin` and `layout` say what was chosen and why.
ImpostorAtlas bake_impostor_auto(std::span<const BakePart> parts, ImpostorSettings settings);

}  // namespace sylva
