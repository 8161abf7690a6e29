#include "export/index_colors.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <map>

#include "core/disjoint_sets.h"
#include "export/part_attributes.h"

namespace sylva {
namespace {

// Multiplies the vertex's tint (white when there is none yet) by `color`.
void apply(PartAttributes& attributes, std::size_t vertices, std::size_t v,
           const glm::vec3& color) {
    if (attributes.tint.size() != vertices) attributes.tint.assign(vertices, glm::vec3(1.0f));
    attributes.tint[v] *= color;
}

std::array<std::uint32_t, 3> bits_of(const glm::vec3& p) {
    std::array<std::uint32_t, 3> bits;
    std::memcpy(bits.data(), &p, sizeof bits);
    return bits;
}

}  // namespace

glm::vec3 palette_color(const std::vector<glm::vec3>& palette, int index) {
    if (palette.empty()) return glm::vec3(1.0f);
    const auto n = static_cast<long long>(palette.size());
    const long long i = ((static_cast<long long>(index) % n) + n) % n;
    return palette[static_cast<std::size_t>(i)];
}

void color_trunk_by_index(NamedMesh& part, PartAttributes& attributes, const Skeleton& skeleton,
                          const std::vector<glm::vec3>& palette) {
    if (palette.empty() || !part.mesh) return;
    const Mesh& mesh = *part.mesh;
    const std::vector<int> owner = owning_segments(mesh, skeleton);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const int s = owner[v];
        apply(attributes, mesh.positions.size(), v,
              palette_color(palette,
                            s < 0 ? 0 : skeleton.segments[static_cast<std::size_t>(s)].color));
    }
    part.color = glm::vec3(1.0f);
}

void color_leaves_by_index(NamedMesh& part, PartAttributes& attributes, const Skeleton& skeleton,
                           const std::vector<glm::vec3>& palette) {
    if (palette.empty() || !part.mesh || skeleton.polygons.empty()) return;
    const Mesh& mesh = *part.mesh;
    // A leaf is the vertices its triangles join; its base is its first (smallest) vertex.
    DisjointSets sets(mesh.positions.size());
    for (const auto& t : mesh.triangles) {
        sets.unite(t[0], t[1]);
        sets.unite(t[0], t[2]);
    }
    std::vector<std::uint32_t> base(mesh.positions.size(), UINT32_MAX);
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        std::uint32_t& b = base[sets.find(v)];
        b = std::min(b, v);
    }
    // Polygon leaves start at their polygon's first vertex (thinning keeps a leaf's base).
    std::map<std::array<std::uint32_t, 3>, int> polygon_at;
    for (std::size_t k = 0; k < skeleton.polygons.size(); ++k)
        if (!skeleton.polygons[k].empty())
            polygon_at.emplace(bits_of(skeleton.polygons[k].front()), polygon_color(skeleton, k));
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const auto found = polygon_at.find(bits_of(mesh.positions[base[sets.find(v)]]));
        apply(attributes, mesh.positions.size(), v,
              found != polygon_at.end() ? palette_color(palette, found->second) : part.color);
    }
    part.color = glm::vec3(1.0f);
}

void color_organs_by_index(NamedMesh& part, PartAttributes& attributes, const OrganMesh& organs,
                           const std::vector<glm::vec3>& palette) {
    if (palette.empty()) return;
    for (std::size_t v = 0; v < organs.color.size(); ++v)
        apply(attributes, organs.color.size(), v, palette_color(palette, organs.color[v]));
    part.color = glm::vec3(1.0f);
}

}  // namespace sylva
