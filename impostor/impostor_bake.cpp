#include "impostor/impostor_bake.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "impostor/impostor_layout.h"

namespace sylva {
namespace {

// The linear value halfway between sRGB bytes b and b + 1, for b in [0, 254]: a byte is
// found by binary search, exact and without a pow per pixel.
const std::array<float, 255>& srgb_thresholds() {
    static const std::array<float, 255> thresholds = [] {
        std::array<float, 255> t{};
        for (int b = 0; b < 255; ++b) {
            const double s = (b + 0.5) / 255.0;
            t[static_cast<std::size_t>(b)] =
                static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return thresholds;
}

std::uint8_t unit_byte(float value) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

// Writes a captured view into tile (column, row) of `albedo` and `normal`; `frame_normals`
// expresses normals in the view's frame (right, up, direction) instead of object space.
void put_tile(const ViewImage& view, const ViewFrame& frame, bool frame_normals, int column,
              int row, Image8& albedo, Image8& normal, float radius) {
    const int tile = view.size;
    for (int y = 0; y < tile; ++y)
        for (int x = 0; x < tile; ++x) {
            const std::size_t p = static_cast<std::size_t>(y * tile + x);
            if (view.alpha[p] <= 0.0f) continue;  // stays 0 until dilation
            const std::size_t at =
                static_cast<std::size_t>((row * tile + y) * albedo.width + column * tile + x);
            std::uint8_t* a = &albedo.pixels[at * 4];
            a[0] = srgb_byte(view.color[p].r);
            a[1] = srgb_byte(view.color[p].g);
            a[2] = srgb_byte(view.color[p].b);
            a[3] = std::max<std::uint8_t>(1, unit_byte(view.alpha[p]));
            glm::vec3 n = view.normal[p];
            if (frame_normals)
                n = {glm::dot(n, frame.right), glm::dot(n, frame.up), glm::dot(n, frame.direction)};
            std::uint8_t* o = &normal.pixels[at * static_cast<std::size_t>(normal.channels)];
            o[0] = unit_byte(n.x * 0.5f + 0.5f);
            o[1] = unit_byte(n.y * 0.5f + 0.5f);
            o[2] = unit_byte(n.z * 0.5f + 0.5f);
            if (normal.channels == 4) o[3] = unit_byte(0.5f + view.depth[p] / (2.0f * radius));
        }
}

Image8 blank(int width, int height, int channels) {
    Image8 image{width, height, channels, {}};
    image.pixels.assign(static_cast<std::size_t>(width * height * channels), 0);
    return image;
}

}  // namespace

std::uint8_t srgb_byte(float linear) {
    if (!(linear > 0.0f)) return 0;
    const auto& t = srgb_thresholds();
    return static_cast<std::uint8_t>(std::upper_bound(t.begin(), t.end(), linear) - t.begin());
}

float srgb_to_linear(std::uint8_t value) {
    const float s = static_cast<float>(value) / 255.0f;
    return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}

ImpostorSettings clamped(ImpostorSettings s) {
    s.views = std::clamp(s.views, 2, 32);
    s.samples = std::clamp(s.samples, 1, 8);
    if (s.size != 0) s.size = std::max(s.size, 8 * s.views);
    s.billboard_quads = std::clamp(s.billboard_quads, 2, 3);
    if (s.billboard_tile <= 0) s.billboard_tile = (s.size != 0 ? s.size : 1024) / 4;
    s.billboard_tile = std::max(s.billboard_tile, 8);
    return s;
}

glm::vec3 billboard_direction(int k, int quads) {
    const double a = std::numbers::pi * k / quads;
    return {static_cast<float>(std::sin(a)), 0.0f, static_cast<float>(std::cos(a))};
}

ImpostorAtlas bake_impostor(std::span<const BakePart> parts, const ImpostorSettings& settings) {
    const ImpostorSettings s = clamped(settings);
    if (s.size == 0) return bake_impostor_auto(parts, s);
    ImpostorAtlas atlas;
    atlas.views = s.views;
    atlas.tile = s.size / s.views;
    atlas.bounds = bake_bounds(parts);
    atlas.depth = s.depth;
    const int side = atlas.tile * s.views;
    atlas.albedo = blank(side, side, 4);
    atlas.normal = blank(side, side, s.depth ? 4 : 3);
    tbb::parallel_for(0, s.views * s.views, [&](int v) {
        const int i = v % s.views, j = v / s.views;
        const ViewFrame frame = view_frame(view_direction(i, j, s.views));
        thread_local ViewImage view;
        render_view(parts, frame, atlas.bounds, atlas.tile, s.samples, view);
        put_tile(view, frame, false, i, j, atlas.albedo, atlas.normal, atlas.bounds.radius);
    });
    Image8* others[] = {&atlas.normal};
    dilate_tiles(atlas.albedo, atlas.tile, others);
    return atlas;
}

BillboardTexture bake_billboard(std::span<const BakePart> parts, const ImpostorSettings& settings) {
    const ImpostorSettings s = clamped(settings);
    BillboardTexture out;
    out.quads = s.billboard_quads;
    out.tile = s.billboard_tile;
    out.bounds = bake_bounds(parts);
    out.albedo = blank(out.tile * out.quads, out.tile, 4);
    out.normal = blank(out.tile * out.quads, out.tile, 3);
    tbb::parallel_for(0, out.quads, [&](int k) {
        const ViewFrame frame = view_frame(billboard_direction(k, out.quads));
        const ViewImage view = render_view(parts, frame, out.bounds, out.tile, s.samples);
        put_tile(view, frame, true, k, 0, out.albedo, out.normal, out.bounds.radius);
    });
    Image8* others[] = {&out.normal};
    dilate_tiles(out.albedo, out.tile, others);
    return out;
}

void dilate_tiles(Image8& coverage, int tile, std::span<Image8* const> others) {
    if (tile <= 0 || coverage.channels != 4) return;
    const int columns = coverage.width / tile, rows = coverage.height / tile;
    tbb::parallel_for(0, columns * rows, [&](int t) {
        const int x0 = (t % columns) * tile, y0 = (t / columns) * tile;
        const std::size_t pixels = static_cast<std::size_t>(tile * tile);
        std::vector<std::int32_t> source(pixels, -1);  // tile-local index of the nearest
        std::vector<std::int32_t> queue;
        queue.reserve(pixels);
        auto global = [&](std::int32_t local) {
            return static_cast<std::size_t>((y0 + local / tile) * coverage.width + x0 +
                                            local % tile);
        };
        for (std::int32_t p = 0; p < static_cast<std::int32_t>(pixels); ++p)
            if (coverage.pixels[global(p) * 4 + 3] > 0) {
                source[static_cast<std::size_t>(p)] = p;
                queue.push_back(p);
            }
        if (queue.empty() || queue.size() == pixels) return;
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const std::int32_t p = queue[head], x = p % tile, y = p / tile;
            const std::int32_t near[4] = {x > 0 ? p - 1 : -1, x + 1 < tile ? p + 1 : -1,
                                          y > 0 ? p - tile : -1, y + 1 < tile ? p + tile : -1};
            for (std::int32_t q : near)
                if (q >= 0 && source[static_cast<std::size_t>(q)] < 0) {
                    source[static_cast<std::size_t>(q)] = source[static_cast<std::size_t>(p)];
                    queue.push_back(q);
                }
        }
        auto copy = [&](Image8& image, std::size_t channels) {
            const std::size_t c = static_cast<std::size_t>(image.channels);
            for (std::int32_t p = 0; p < static_cast<std::int32_t>(pixels); ++p) {
                const std::int32_t from = source[static_cast<std::size_t>(p)];
                if (from == p) continue;
                const std::size_t to = global(p) * c, src = global(from) * c;
                for (std::size_t k = 0; k < channels; ++k)
                    image.pixels[to + k] = image.pixels[src + k];
            }
        };
        copy(coverage, 3);
        for (Image8* other : others) copy(*other, static_cast<std::size_t>(other->channels));
    });
}

}  // namespace sylva
