#include "export/impostor_level.h"

#include <oneapi/tbb/parallel_invoke.h>

#include "export/glb_writer.h"
#include "impostor/impostor_files.h"
#include "impostor/impostor_mesh.h"

namespace sylva {
namespace {

// Adds `quads` as a level of one part named `name` with its textures.
void add_level(EngineModel& model, TexturedMesh quads, const std::string& name,
               PartTextures textures) {
    model.far_meshes.push_back(std::move(quads.mesh));
    PartAttributes attributes;
    attributes.uv = std::move(quads.uv);
    model.attributes.push_back(std::move(attributes));
    model.textures.push_back(std::move(textures));
    NamedMesh part;
    part.name = name;
    part.mesh = &model.far_meshes.back();
    part.color = glm::vec3(1.0f);
    part.closed = false;  // a card: seen from both sides
    part.attributes = &model.attributes.back();
    part.textures = &model.textures.back();
    model.levels.push_back({part});
}

// The two PNGs at once (zlib runs on one thread each).
void encode_both(const Image8& albedo, const Image8& normal, PartTextures& textures) {
    tbb::parallel_invoke([&] { textures.albedo_png = encode_png(albedo); },
                         [&] { textures.normal_png = encode_png(normal); });
}

ImpostorSettings settings_of(const ImpostorOptions& options) {
    ImpostorSettings s;
    s.size = options.size;
    s.views = options.views;
    s.depth = options.depth;
    s.billboard_quads = options.billboard_quads;
    return clamped(s);
}

}  // namespace

ImpostorImageNames impostor_image_names(const std::filesystem::path& path, bool embedded) {
    auto name = [&](const char* texture, const char* map) {
        return embedded ? std::string(texture) + "_" + map
                        : texture_file_name(path, texture, map).filename().string();
    };
    return {name("impostor", "albedo"), name("impostor", "normal"), name("billboard", "albedo"),
            name("billboard", "normal")};
}

void add_far_levels(EngineModel& model, const ExportOptions& options) {
    const ImpostorKind kind = options.impostor.kind;
    const ImpostorSettings settings = settings_of(options.impostor);
    const std::vector<BakePart> parts = bake_parts(model.levels[0]);
    const ImpostorImageNames embedded = impostor_image_names({}, true);
    if (kind == ImpostorKind::Billboard || kind == ImpostorKind::Both) {
        BillboardTexture billboard = bake_billboard(parts, settings);
        PartTextures textures{
            "billboard", {}, {}, 0.5f, impostor_layout_json(nullptr, &billboard, embedded)};
        encode_both(billboard.albedo, billboard.normal, textures);
        add_level(model, billboard_quads(billboard), "billboard", std::move(textures));
        billboard.albedo.pixels = {};
        billboard.normal.pixels = {};
        model.billboard = std::move(billboard);
    }
    if (kind == ImpostorKind::Octahedral || kind == ImpostorKind::Both) {
        ImpostorAtlas atlas = bake_impostor(parts, settings);
        PartTextures textures{
            "impostor", {}, {}, 0.5f, impostor_layout_json(&atlas, nullptr, embedded)};
        encode_both(atlas.albedo, atlas.normal, textures);
        add_level(model, impostor_quad(atlas), "impostor", std::move(textures));
        atlas.albedo.pixels = {};
        atlas.normal.pixels = {};
        model.atlas = std::move(atlas);
    }
}

std::string far_levels_layout(const EngineModel& model, const std::filesystem::path& path,
                              const ExportFormat* format) {
    return impostor_layout_json(model.atlas ? &*model.atlas : nullptr,
                                model.billboard ? &*model.billboard : nullptr,
                                impostor_image_names(path, format == &glb_format));
}

}  // namespace sylva
