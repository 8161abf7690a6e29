// Baking a finished tree into impostor textures, headless: the octahedral atlas (N x N
// views of the upper hemisphere, hemi_octahedral.h) that an engine's shader turns with the
// camera, and the billboard texture of a few side views that crossed quads show in any
// importer without a shader. Colour is sRGB with straight alpha, normals linear; the
// colour and normal of every transparent pixel are those of the nearest covered pixel of
// its tile (dilation), so mipmaps and filtering do not pull a dark halo into the edges.
// Deterministic: the same parts and settings give the same bytes on any machine and any
// number of threads. Thread-safe; runs its views on the TBB pool.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "impostor/view_rasterizer.h"

namespace sylva {

struct ImpostorSettings {
    int views = 8;  // N: N x N views (2 to 32)
    // The atlas side in pixels; a tile is size / N (at least 8). 0: automatic, the layout
    // chosen per tree by its thinness (impostor_layout.h), `views` the default's count.
    int size = 1024;
    int samples = 2;  // per pixel and axis (1 to 8): anti-aliased alpha edges
    // The normal atlas carries depth in alpha (RGBA instead of RGB), which the shaders use to
    // line the three views up (atlas_sampler.h); without it they blend the views as captured
    // and thin far parts (palm fronds) ghost between views.
    bool depth = true;
    int billboard_quads = 3;  // crossed quads of the billboard (2 or 3)
    int billboard_tile = 0;   // a billboard view's side in pixels; 0: size / 4
};

// Pixels, rows top down, `channels` bytes a pixel (3 or 4).
struct Image8 {
    int width = 0, height = 0, channels = 4;
    std::vector<std::uint8_t> pixels;
};

// The octahedral impostor: view (i, j) fills the tile at column i, row j. Albedo is RGBA
// (sRGB colour, alpha = coverage); normal is object space as n * 0.5 + 0.5 (linear), with
// depth in alpha when asked: 0.5 + d / (2 r), d the distance toward the camera from the
// plane through the centre.
struct ImpostorAtlas {
    int views = 0;
    int tile = 0;  // pixels a view
    BakeBounds bounds;
    bool depth = false;
    double thin = -1.0;  // thin_share() of the default layout, when the layout was automatic
    std::string layout;  // when automatic: one line saying what was chosen and why
    Image8 albedo;
    Image8 normal;
};

// The billboard: quad k looks along (sin a, 0, cos a), a = k * 180 / quads degrees, and its
// view fills tile k of one row. Normals are in each quad's own frame (right, up, toward the
// camera): a tangent-space normal map for the quad.
struct BillboardTexture {
    int quads = 0;
    int tile = 0;
    BakeBounds bounds;
    Image8 albedo;
    Image8 normal;
};

// Clamps settings to their ranges (views 2-32, samples 1-8, tile >= 8, quads 2-3); size 0
// (automatic) stays, its billboard tiles of 256 px.
ImpostorSettings clamped(ImpostorSettings settings);

ImpostorAtlas bake_impostor(std::span<const BakePart> parts, const ImpostorSettings& settings);
BillboardTexture bake_billboard(std::span<const BakePart> parts, const ImpostorSettings& settings);

// The direction of billboard quad k of `quads`.
glm::vec3 billboard_direction(int k, int quads);

// Dilation: within each `tile` x `tile` square of `coverage` (an Image8 whose alpha is
// channel 3), every pixel of alpha 0 gets the colour channels (0-2) of its nearest pixel
// of alpha > 0 (breadth first over 4-neighbours, ties by scan order), in `coverage`, and
// every channel of that pixel in each of `others` (same size: the normals and depth, which
// filtered reads near an edge mix in). Coverage's alpha stays; a tile with no covered pixel
// stays.
void dilate_tiles(Image8& coverage, int tile, std::span<Image8* const> others = {});

// Linear [0, 1] to an sRGB byte, and back.
std::uint8_t srgb_byte(float linear);
float srgb_to_linear(std::uint8_t value);

}  // namespace sylva
