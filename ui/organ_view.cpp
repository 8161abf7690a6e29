#include "ui/organ_view.h"

#include <map>

#include "export/index_colors.h"

namespace sylva::studio {

void upload_organs(OrganView& view, const OrganMesh& organs) {
    std::map<int, Mesh> by_color;
    for (std::size_t k = 0; k < organs.organs(); ++k) {
        const std::uint32_t v0 = organs.first_vertex[k], v1 = organs.first_vertex[k + 1];
        Mesh& mesh = by_color[organs.color.empty() || v0 == v1 ? 0 : organs.color[v0]];
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), organs.mesh.positions.begin() + v0,
                              organs.mesh.positions.begin() + v1);
        for (std::uint32_t t = organs.first_triangle[k]; t < organs.first_triangle[k + 1]; ++t) {
            const auto& tri = organs.mesh.triangles[t];
            const std::array<std::uint32_t, 3> own{tri[0] - v0 + first, tri[1] - v0 + first,
                                                   tri[2] - v0 + first};
            mesh.triangles.push_back(own);
            // The renderer culls back faces: a polygon shows its other side too.
            if (organs.polygon[k]) mesh.triangles.push_back({own[0], own[2], own[1]});
        }
    }
    while (view.renderers.size() < by_color.size())
        view.renderers.push_back(std::make_unique<MeshRenderer>());
    view.indices.clear();
    std::size_t i = 0;
    for (const auto& [index, mesh] : by_color) {
        view.renderers[i++]->upload(mesh);
        view.indices.push_back(index);
    }
}

void draw_organs(const OrganView& organs, const glm::mat4& view, const glm::mat4& projection,
                 const PartColors& colors, bool wireframe, const glm::vec3& wire_color) {
    for (std::size_t i = 0; i < organs.indices.size(); ++i) {
        const glm::vec3 color = colors.palette.empty()
                                    ? colors.leaves
                                    : palette_color(colors.palette, organs.indices[i]);
        organs.renderers[i]->draw(view, projection, color);
        if (wireframe) organs.renderers[i]->draw_wireframe(view, projection, wire_color);
    }
}

}  // namespace sylva::studio
