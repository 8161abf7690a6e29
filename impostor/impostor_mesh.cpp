#include "impostor/impostor_mesh.h"

namespace sylva {
namespace {

// A quad through `center` spanning right * [-r, r] and up * [-r, r], counter-clockwise
// seen from direction, with UVs on the image rectangle [u0, u1] x [top, bottom] (image
// coordinates, y down) of an image w x h pixels.
void add_quad(TexturedMesh& out, const glm::vec3& center, float r, const ViewFrame& frame,
              glm::vec2 top_left, glm::vec2 bottom_right, glm::vec2 image) {
    const auto base = static_cast<std::uint32_t>(out.mesh.positions.size());
    const glm::vec3 x = r * frame.right, y = r * frame.up;
    out.mesh.positions.insert(out.mesh.positions.end(),
                              {center - x - y, center + x - y, center + x + y, center - x + y});
    // v up the image: 1 - y / height.
    const glm::vec2 lo(top_left.x / image.x, 1.0f - bottom_right.y / image.y);
    const glm::vec2 hi(bottom_right.x / image.x, 1.0f - top_left.y / image.y);
    const glm::vec2 corner[4] = {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}};
    out.mesh.triangles.push_back({base, base + 1, base + 2});
    out.uv.push_back({corner[0], corner[1], corner[2]});
    out.mesh.triangles.push_back({base, base + 2, base + 3});
    out.uv.push_back({corner[0], corner[2], corner[3]});
}

}  // namespace

glm::ivec2 front_view(int views) {
    return {views - 1, 0};
}

TexturedMesh impostor_quad(const ImpostorAtlas& atlas) {
    TexturedMesh out;
    const glm::ivec2 v = front_view(atlas.views);
    const float t = static_cast<float>(atlas.tile);
    add_quad(out, atlas.bounds.center, atlas.bounds.radius,
             view_frame(view_direction(v.x, v.y, atlas.views)),
             {static_cast<float>(v.x) * t, static_cast<float>(v.y) * t},
             {static_cast<float>(v.x + 1) * t, static_cast<float>(v.y + 1) * t},
             {static_cast<float>(atlas.albedo.width), static_cast<float>(atlas.albedo.height)});
    return out;
}

TexturedMesh billboard_quads(const BillboardTexture& billboard) {
    TexturedMesh out;
    const float t = static_cast<float>(billboard.tile);
    for (int k = 0; k < billboard.quads; ++k)
        add_quad(out, billboard.bounds.center, billboard.bounds.radius,
                 view_frame(billboard_direction(k, billboard.quads)),
                 {static_cast<float>(k) * t, 0.0f}, {static_cast<float>(k + 1) * t, t},
                 {static_cast<float>(billboard.albedo.width),
                  static_cast<float>(billboard.albedo.height)});
    return out;
}

}  // namespace sylva
