#include "impostor/atlas_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

namespace sylva {
namespace {

struct Texel {
    float alpha = 0.0f;
    glm::vec3 color{0.0f};
    glm::vec3 normal{0.0f};
};

// Bilinear sample of tile (i, j) at tile pixel coordinates (x, y) (pixel centres at
// half-integers); texels outside the tile count as transparent, so no neighbour bleeds in.
Texel sample_tile(const ImpostorAtlas& atlas, glm::ivec2 view, float x, float y,
                  const std::array<float, 256>& linear) {
    const int tile = atlas.tile;
    const float fx = x - 0.5f, fy = y - 0.5f;
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
    const float tx = fx - static_cast<float>(x0), ty = fy - static_cast<float>(y0);
    Texel out;
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
            const int px = x0 + dx, py = y0 + dy;
            if (px < 0 || py < 0 || px >= tile || py >= tile) continue;
            const float w = (dx ? tx : 1.0f - tx) * (dy ? ty : 1.0f - ty);
            const std::size_t at = static_cast<std::size_t>(
                (view.y * tile + py) * atlas.albedo.width + view.x * tile + px);
            const std::uint8_t* a = &atlas.albedo.pixels[at * 4];
            const std::uint8_t* n =
                &atlas.normal.pixels[at * static_cast<std::size_t>(atlas.normal.channels)];
            out.alpha += w * static_cast<float>(a[3]) / 255.0f;
            out.color += w * glm::vec3(linear[a[0]], linear[a[1]], linear[a[2]]);
            out.normal += w * (glm::vec3(n[0], n[1], n[2]) / 255.0f * 2.0f - 1.0f);
        }
    return out;
}

// Whether tile (i, j)'s surface is where the ray is: the texel under tile pixel coordinates
// (x, y) (nearest, no filtering: a bilinear depth between a near twig and the trunk behind
// it is a surface that is nowhere) is covered at all, and `along` (the point's distance
// toward the view from the plane through the centre) lies from `band` behind its depth to
// its depth.
bool on_surface(const ImpostorAtlas& atlas, glm::ivec2 view, float x, float y, float along,
                float band) {
    const int tile = atlas.tile;
    const int px = static_cast<int>(std::floor(x)), py = static_cast<int>(std::floor(y));
    if (px < 0 || py < 0 || px >= tile || py >= tile) return false;
    const std::size_t at =
        static_cast<std::size_t>((view.y * tile + py) * atlas.albedo.width + view.x * tile + px);
    if (atlas.albedo.pixels[at * 4 + 3] == 0) return false;
    const float depth = (static_cast<float>(atlas.normal.pixels[at * 4 + 3]) / 255.0f - 0.5f) *
                        2.0f * atlas.bounds.radius;
    return along <= depth && along >= depth - band;
}

}  // namespace

std::optional<glm::vec2> impostor_relief_hit(const ImpostorAtlas& atlas, glm::ivec2 view,
                                             const ViewFrame& frame, glm::vec3 on_quad,
                                             glm::vec3 toward_camera) {
    const float r = atlas.bounds.radius;
    const float tile = static_cast<float>(atlas.tile);
    const float step = 2.0f * r / static_cast<float>(kImpostorReliefSteps);
    const float band = kImpostorSurfaceTexels * 2.0f * r / tile + step;
    auto tile_point = [&](float s) {
        const glm::vec3 p = on_quad + toward_camera * s;
        return glm::vec3((glm::dot(p, frame.right) / r * 0.5f + 0.5f) * tile,
                         (0.5f - glm::dot(p, frame.up) / r * 0.5f) * tile,
                         glm::dot(p, frame.direction));
    };
    auto hit = [&](float s) {
        const glm::vec3 t = tile_point(s);
        return on_surface(atlas, view, t.x, t.y, t.z, band);
    };
    for (int i = 0; i <= kImpostorReliefSteps; ++i) {
        const float s = r - step * static_cast<float>(i);
        if (!hit(s)) continue;
        // The first hit lies between the previous step (no hit) and this one: halve that.
        float front = s + step, back = s;
        if (i > 0)
            for (int k = 0; k < kImpostorReliefRefinements; ++k) {
                const float middle = 0.5f * (front + back);
                (hit(middle) ? back : front) = middle;
            }
        const glm::vec3 t = tile_point(back);
        return glm::vec2(t.x, t.y);
    }
    return std::nullopt;
}

ViewImage render_impostor(const ImpostorAtlas& atlas, const ViewFrame& camera, int size) {
    ViewImage image;
    image.size = size;
    const std::size_t pixels = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
    image.alpha.assign(pixels, 0.0f);
    image.color.assign(pixels, glm::vec3(0.0f));
    image.normal.assign(pixels, glm::vec3(0.0f));
    image.depth.assign(pixels, 0.0f);
    const float r = atlas.bounds.radius;
    if (size <= 0 || !(r > 0.0f) || atlas.tile <= 0) return image;

    std::array<float, 256> linear{};
    for (int b = 0; b < 256; ++b)
        linear[static_cast<std::size_t>(b)] = srgb_to_linear(static_cast<std::uint8_t>(b));
    const ViewBlend blend = view_blend(camera.direction, atlas.views);
    std::array<ViewFrame, 3> frames;
    for (int k = 0; k < 3; ++k) {
        const glm::ivec2 v = blend.views[static_cast<std::size_t>(k)];
        frames[static_cast<std::size_t>(k)] = view_frame(view_direction(v.x, v.y, atlas.views));
    }
    const float tile = static_cast<float>(atlas.tile);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            // The pixel's centre on the quad (the camera's plane through the centre).
            const float a =
                ((static_cast<float>(x) + 0.5f) / static_cast<float>(size) * 2.0f - 1.0f) * r;
            const float b =
                (1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(size) * 2.0f) * r;
            const glm::vec3 on_quad = a * camera.right + b * camera.up;  // from the centre
            Texel sum;
            float hit_weight = 0.0f;  // of the views whose surface the ray meets
            for (std::size_t k = 0; k < 3; ++k) {
                const float w = blend.weights[k];
                if (w <= 0.0f) continue;
                const ViewFrame& f = frames[k];
                const float facing = glm::dot(camera.direction, f.direction);
                if (facing <= 1e-4f) continue;
                glm::vec2 at;
                if (atlas.depth) {
                    const std::optional<glm::vec2> hit =
                        impostor_relief_hit(atlas, blend.views[k], f, on_quad, camera.direction);
                    if (!hit) continue;  // the ray misses this view's surface: alpha 0
                    at = *hit;
                } else {
                    // Without depth: where the ray meets the view's plane through the centre.
                    const glm::vec3 p =
                        on_quad - camera.direction * (glm::dot(on_quad, f.direction) / facing);
                    at = {(glm::dot(p, f.right) / r * 0.5f + 0.5f) * tile,
                          (0.5f - glm::dot(p, f.up) / r * 0.5f) * tile};
                }
                const Texel t = sample_tile(atlas, blend.views[k], at.x, at.y, linear);
                sum.alpha += w * t.alpha;
                sum.color += w * t.color;
                sum.normal += w * t.normal;
                hit_weight += w;
            }
            const std::size_t p = static_cast<std::size_t>(y * size + x);
            image.alpha[p] = std::min(sum.alpha * kImpostorCoverageGain, 1.0f);
            if (!(hit_weight > 0.0f) || sum.alpha <= 0.0f) continue;
            image.color[p] = sum.color / hit_weight;
            const float length = glm::length(sum.normal);
            if (length > 0.0f) image.normal[p] = sum.normal / length;
        }
    return image;
}

}  // namespace sylva
