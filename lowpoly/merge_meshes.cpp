#include "lowpoly/merge_meshes.h"

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

}  // namespace sylva
