#include "export/leaf_atlas.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>
#include <vector>

#include "core/random.h"
#include "impostor/impostor_bake.h"
#include "impostor/impostor_files.h"
#include "tree/leaves.h"

namespace sylva {
namespace {

// Leaves along the midrib, alternating sides, from the base to the tip of the card.
constexpr int kLeaves = 15;

// Whether p lies inside the closed polygon (even-odd rule).
bool inside(const std::vector<glm::vec2>& polygon, const glm::vec2& p) {
    bool in = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const glm::vec2& a = polygon[i];
        const glm::vec2& b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            in = !in;
    }
    return in;
}

}  // namespace

PartTextures leaf_atlas(LeafShape shape, const glm::vec3& color, int size, std::uint64_t seed) {
    Image8 image;
    image.width = image.height = size;
    image.channels = 4;
    image.pixels.assign(static_cast<std::size_t>(size) * size * 4, 0);
    const std::vector<glm::vec2>& outline = leaf_outline(shape);
    Random random(seed ^ 0x1eafa71a5ULL);
    for (int k = 0; k < kLeaves; ++k) {
        // Where along the midrib (v) it starts, to which side it leans, how long it is.
        const float t = (static_cast<float>(k) + 0.5f) / kLeaves;
        const float v = 0.08f + 0.8f * t;
        const float side = k % 2 == 0 ? 1.0f : -1.0f;
        const float lean = side * (0.55f + 0.35f * static_cast<float>(random.uniform()));
        const float length =
            0.34f * (1.0f - 0.45f * t) + 0.04f * static_cast<float>(random.uniform());
        const glm::vec2 along(std::sin(lean), std::cos(lean));
        const glm::vec2 across(along.y, -along.x);
        std::vector<glm::vec2> leaf;
        for (const glm::vec2& q : outline)
            leaf.push_back(glm::vec2(0.5f, v) + (along * q.x + across * q.y) * length);
        glm::vec2 lo(1.0f), hi(0.0f);
        for (const glm::vec2& q : leaf) lo = glm::min(lo, q), hi = glm::max(hi, q);
        const float shade = 0.8f + 0.4f * static_cast<float>(random.uniform());
        const std::array<std::uint8_t, 3> rgb = {
            srgb_byte(color.r * shade), srgb_byte(color.g * shade), srgb_byte(color.b * shade)};
        const int x0 = std::max(0, static_cast<int>(lo.x * size)),
                  x1 = std::min(size - 1, static_cast<int>(hi.x * size));
        const int y0 = std::max(0, static_cast<int>(lo.y * size)),
                  y1 = std::min(size - 1, static_cast<int>(hi.y * size));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 p((static_cast<float>(x) + 0.5f) / size,
                                  (static_cast<float>(y) + 0.5f) / size);
                // Only inside the card's diamond, and in the leaf.
                if (std::abs(p.x - 0.5f) + std::abs(p.y - 0.5f) > 0.5f || !inside(leaf, p))
                    continue;
                // Rows from the top of the image: v runs up the card.
                std::uint8_t* px =
                    &image.pixels[(static_cast<std::size_t>(size - 1 - y) * size + x) * 4];
                px[0] = rgb[0], px[1] = rgb[1], px[2] = rgb[2], px[3] = 255;
            }
    }
    dilate_tiles(image, size);
    PartTextures out;
    out.name = "leaves";
    out.albedo_png = encode_png(image);
    out.alpha_cutoff = 0.5f;
    return out;
}

}  // namespace sylva
