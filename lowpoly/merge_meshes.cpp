#include "lowpoly/merge_meshes.h"

#include <array>
#include <limits>

#include "core/disjoint_sets.h"

namespace sylva {

Mesh merge_meshes(std::span<const Mesh* const> meshes) {
    Mesh out;
    std::size_t nv = 0, nt = 0;
    for (const Mesh* m : meshes)
        if (m) {
            nv += m->positions.size();
            nt += m->triangles.size();
        }
    out.positions.reserve(nv);
    out.triangles.reserve(nt);
    for (const Mesh* m : meshes) {
        if (!m) continue;
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        out.positions.insert(out.positions.end(), m->positions.begin(), m->positions.end());
        for (const auto& t : m->triangles)
            out.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    return out;
}

std::vector<std::uint32_t> component_of_triangles(const Mesh& mesh, std::size_t& count) {
    DisjointSets sets(mesh.positions.size());
    for (const auto& t : mesh.triangles) {
        sets.unite(t[1], t[0]);
        sets.unite(t[2], t[0]);
    }
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> component_of_root(mesh.positions.size(), kNone);
    std::vector<std::uint32_t> component(mesh.triangles.size());
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        std::uint32_t& c = component_of_root[sets.find(mesh.triangles[i][0])];
        if (c == kNone) c = next++;
        component[i] = c;
    }
    count = next;
    return component;
}

std::vector<Mesh> split_by_label(const Mesh& mesh, std::span<const std::uint32_t> label,
                                 std::size_t count) {
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<Mesh> out(count);
    std::vector<std::uint32_t> index(mesh.positions.size(), kNone);
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        if (label[i] >= count) continue;
        Mesh& m = out[label[i]];
        std::array<std::uint32_t, 3> u{};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.triangles[i][k];
            if (index[v] == kNone) {  // a vertex belongs to one component, so to one mesh
                index[v] = static_cast<std::uint32_t>(m.positions.size());
                m.positions.push_back(mesh.positions[v]);
            }
            u[k] = index[v];
        }
        m.triangles.push_back(u);
    }
    return out;
}

}  // namespace sylva
