#include "export/palette.h"

#include <algorithm>
#include <cmath>

// The implementation comes from libstb (pkg-config stb), as in ui/screenshot.cpp.
#include <stb/stb_image_write.h>

namespace sylva {
namespace {

int part_row(std::string_view part) {
    return part == "trunk" ? 0 : part == "crown" ? 1 : 2;
}

float shade_factor(int shade) {
    return 1.0f - 0.35f * static_cast<float>(shade) / (kPaletteShades - 1);
}

std::uint8_t srgb8(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

}  // namespace

std::vector<std::uint8_t> palette_png(const PartColors& colors) {
    constexpr int width = kPaletteShades * kPaletteSwatch, height = 3 * kPaletteSwatch;
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width * height * 3));
    const glm::vec3 rows[3] = {colors.trunk, colors.crown, colors.leaves};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            // Image rows run top down; row 0 (trunk) is at the bottom, where v = 0 is.
            const int row = 2 - y / kPaletteSwatch;
            const glm::vec3 c = rows[row] * shade_factor(x / kPaletteSwatch);
            std::uint8_t* p = &pixels[static_cast<std::size_t>((y * width + x) * 3)];
            p[0] = srgb8(c.r);
            p[1] = srgb8(c.g);
            p[2] = srgb8(c.b);
        }
    std::vector<std::uint8_t> png;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* out = static_cast<std::vector<std::uint8_t>*>(context);
            const auto* bytes = static_cast<const std::uint8_t*>(data);
            out->insert(out->end(), bytes, bytes + size);
        },
        &png, width, height, 3, pixels.data(), width * 3);
    return png;
}

void use_palette(PartAttributes& attributes, const Mesh& mesh, std::string_view part) {
    const int row = part_row(part);
    auto swatch = [&](std::uint32_t v) {
        int shade = 0;
        if (!attributes.tint.empty()) {
            const glm::vec3& t = attributes.tint[v];
            const float brightness = (t.r + t.g + t.b) / 3.0f;
            shade = std::clamp(
                static_cast<int>(std::lround((1.0f - brightness) / 0.35f * (kPaletteShades - 1))),
                0, kPaletteShades - 1);
        }
        return glm::vec2((static_cast<float>(shade) + 0.5f) / kPaletteShades,
                         (static_cast<float>(row) + 0.5f) / 3.0f);
    };
    attributes.uv.assign(mesh.triangles.size(), {});
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) attributes.uv[f][k] = swatch(mesh.triangles[f][k]);
}

}  // namespace sylva
