#include "impostor/impostor_files.h"

#include <png.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "impostor/atlas_sampler.h"
#include "impostor/impostor_mesh.h"

namespace sylva {
namespace {

nlohmann::json vec3(const glm::vec3& v) {
    return nlohmann::json::array({v.x, v.y, v.z});
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image8& image) {
    std::vector<std::uint8_t> png;
    png_structp writer = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = writer ? png_create_info_struct(writer) : nullptr;
    if (!info) {
        png_destroy_write_struct(&writer, nullptr);
        throw std::bad_alloc();
    }
    // libpng reports errors by longjmp; nothing here owns memory across the jump but `png`.
    if (setjmp(png_jmpbuf(writer))) {
        png_destroy_write_struct(&writer, &info);
        throw std::runtime_error("libpng could not encode the image");
    }
    png_set_write_fn(
        writer, &png,
        [](png_structp p, png_bytep data, png_size_t size) {
            auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(p));
            out->insert(out->end(), data, data + size);
        },
        nullptr);
    png_set_IHDR(writer, info, static_cast<png_uint_32>(image.width),
                 static_cast<png_uint_32>(image.height), 8,
                 image.channels == 4 ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // zlib's default level with the Sub filter alone: a third of the time of the adaptive
    // filter choice at about the same size (these images are flat colour and dilated runs).
    png_set_compression_level(writer, 6);
    png_set_filter(writer, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_write_info(writer, info);
    const std::size_t stride = static_cast<std::size_t>(image.width * image.channels);
    for (int y = 0; y < image.height; ++y)
        png_write_row(writer, image.pixels.data() + static_cast<std::size_t>(y) * stride);
    png_write_end(writer, info);
    png_destroy_write_struct(&writer, &info);
    return png;
}

std::string impostor_layout_json(const ImpostorAtlas* atlas, const BillboardTexture* billboard,
                                 const ImpostorImageNames& images) {
    nlohmann::json j;
    j["format"] = "sylva-impostor";
    j["version"] = 1;
    if (atlas) {
        const glm::ivec2 front = front_view(atlas->views);
        j["octahedral"] = {
            {"layout", "hemi-octahedral"},
            {"views", atlas->views},
            {"tile", atlas->tile},
            {"atlas_size", {atlas->albedo.width, atlas->albedo.height}},
            {"center", vec3(atlas->bounds.center)},
            {"radius", atlas->bounds.radius},
            {"view_direction",
             "view (i, j) fills column i, row j (rows top down); s = (i, j) / (views - 1) * 2 "
             "- 1; p = ((s.x + s.y) / 2, (s.x - s.y) / 2); direction = normalize(p.x, 1 - "
             "|p.x| - |p.y|, p.y), y up"},
            {"view_camera",
             "right = normalize(cross((0, 1, 0), direction)) ((1, 0, 0) straight above), up = "
             "cross(direction, right); a tile spans center + right * [-radius, radius] left to "
             "right and up * [radius, -radius] top to bottom, orthographic"},
            {"blend",
             "g = (encode(direction) * 0.5 + 0.5) * (views - 1), cell = clamp(floor(g), 0, "
             "views - 2), f = g - cell; f.x + f.y <= 1: views cell, cell + (1, 0), cell + (0, "
             "1) weighted 1 - f.x - f.y, f.x, f.y; else cell + (1, 1), cell + (1, 0), cell + "
             "(0, 1) weighted f.x + f.y - 1, 1 - f.y, 1 - f.x; each view is read (bilinear) "
             "where the camera's ray first meets its surface, a view the ray misses counting as "
             "transparent; the blended alpha times coverage_gain (at most 1) is alpha-tested at "
             "0.5, colour is averaged over the views the ray meets"},
            {"relief",
             "the ray is tested at relief_steps + 1 points evenly from radius toward the camera "
             "to radius away from it, measured from the quad; a point is on the view's surface "
             "where its texel (unfiltered) has alpha > 0 and the point's distance toward the "
             "view from the plane through the center lies from (surface_texels * 2 radius / tile "
             "+ 2 radius / relief_steps) below the texel's depth to that depth; the first such "
             "step is refined by relief_refinements halvings between it and the step before"},
            {"relief_steps", kImpostorReliefSteps},
            {"relief_refinements", kImpostorReliefRefinements},
            {"surface_texels", kImpostorSurfaceTexels},
            {"coverage_gain", kImpostorCoverageGain},
            {"front_view", {front.x, front.y}},
            {"layout_choice", atlas->layout.empty() ? std::string("as asked") : atlas->layout},
            {"albedo",
             {{"image", images.atlas_albedo},
              {"color", "sRGB"},
              {"alpha", "coverage, straight; transparent texels carry the nearest colour"}}},
            {"normal",
             {{"image", images.atlas_normal},
              {"space", "object"},
              {"encoding", "rgb = normal * 0.5 + 0.5, linear"},
              {"depth", atlas->depth ? "alpha = 0.5 + d / (2 radius), d toward the camera from the "
                                       "plane through the center"
                                     : "none"}}},
        };
    }
    if (billboard) {
        nlohmann::json directions = nlohmann::json::array();
        for (int k = 0; k < billboard->quads; ++k)
            directions.push_back(vec3(billboard_direction(k, billboard->quads)));
        j["billboard"] = {
            {"quads", billboard->quads},
            {"tile", billboard->tile},
            {"texture_size", {billboard->albedo.width, billboard->albedo.height}},
            {"center", vec3(billboard->bounds.center)},
            {"radius", billboard->bounds.radius},
            {"directions", directions},
            {"albedo", {{"image", images.billboard_albedo}, {"color", "sRGB"}}},
            {"normal",
             {{"image", images.billboard_normal},
              {"space", "tangent (each quad's right, up, facing)"},
              {"encoding", "rgb = normal * 0.5 + 0.5, linear"}}},
        };
    }
    return j.dump(2);
}

}  // namespace sylva
