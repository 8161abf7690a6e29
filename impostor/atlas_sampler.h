// The CPU reference of the impostor shaders (engine_kits/*/impostor_*, docs/impostors.md):
// the octahedral atlas drawn from any direction of the upper hemisphere as one quad facing
// the camera that blends the three nearest views. Each view is sampled where the camera's
// ray through the quad meets that view's surface, found by marching the ray through the
// view's depth (relief mapping, Policarpo et al. 2005), so the three images line up at every
// depth and a ray that passes beside a twig in one view does not take its colour there.
// Bilinear filtering of linear colour at the hit, as a GPU samples an sRGB texture. What
// the fidelity tests compare with the tree's own rendering (view_rasterizer.h).
// Thread-safe.
#pragma once

#include <glm/vec2.hpp>
#include <optional>

#include "impostor/impostor_bake.h"

namespace sylva {

// The blended alpha is multiplied by this (at most 1) before the 0.5 alpha test, so a texel
// counts from a blended coverage of 0.36 on. The three views, lined up with one depth per
// texel, disagree by about a texel on parts a texel thin (fronds, sprays, twigs), and each
// then contributes only its weight's share of the part's coverage; the lower cut keeps those
// parts while a solid edge moves by a fraction of a texel. A single view's pixel of coverage
// 0.36 to 0.5 counts too (about half a sample of 2 x 2 more). Every shader applies it.
inline constexpr float kImpostorCoverageGain = 1.4f;

// The march through a view's depth: the ray is tested at kImpostorReliefSteps + 1 points
// evenly from radius in front of the centre to radius behind it (the quad's own depth range),
// and the first step that lands on the surface is refined by kImpostorReliefRefinements
// halvings. A texel is surface (the ray has hit it) from its stored depth back to
// kImpostorSurfaceTexels texels plus one step behind it: one step, so no surface is stepped
// over; a few texels, because the atlas stores only each part's front and a ray at another
// angle enters a twig or a trunk through its side. A solid depth (everything behind the
// front) would widen every thin part by its shadow; a thinner band misses more thin parts.
// Every shader uses the same numbers (the layout's `relief_steps`, `surface_texels`).
inline constexpr int kImpostorReliefSteps = 64;
inline constexpr int kImpostorReliefRefinements = 3;
inline constexpr float kImpostorSurfaceTexels = 5.0f;

// Where the camera's ray through `on_quad` (a point on the quad, relative to the atlas's
// centre) first meets the surface of view (i, j), whose camera is `frame`, marching away
// from the camera (`toward_camera`: unit, from the tree toward the camera): the tile pixel
// coordinates (pixel centres at half-integers) of the hit, or nothing if the ray misses.
// Needs an atlas with depth.
std::optional<glm::vec2> impostor_relief_hit(const ImpostorAtlas& atlas, glm::ivec2 view,
                                             const ViewFrame& frame, glm::vec3 on_quad,
                                             glm::vec3 toward_camera);

// The atlas as an orthographic camera looking along -camera.direction sees it: pixel
// (x, y) of the size x size result covers the same square as render_view()'s pixel with
// the same frame and the atlas's bounds. Alpha, colour (linear RGB) and normal (object
// space, unit; zero where alpha is 0) are the weighted sums of the three views read at their
// hits, alpha times kImpostorCoverageGain (at most 1), a view the ray misses counting as
// transparent; colour and normal are averaged over the views the ray hits only. Without
// depth in the atlas, each view is read where the ray meets its plane through the centre.
// Depth is 0.
ViewImage render_impostor(const ImpostorAtlas& atlas, const ViewFrame& camera, int size);

}  // namespace sylva
