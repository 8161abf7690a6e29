#include "export/organ_attributes.h"

#include <algorithm>

#include "core/random.h"

namespace sylva {

PartAttributes organ_attributes(const OrganMesh& organs, const TreeFrame& frame,
                                const EngineSettings& settings) {
    PartAttributes out;
    const Mesh& mesh = organs.mesh;
    if (settings.uvs) {
        out.uv.reserve(mesh.triangles.size());
        for (const auto& t : mesh.triangles)
            out.uv.push_back({organs.uv[t[0]], organs.uv[t[1]], organs.uv[t[2]]});
    }
    if (settings.wind) {
        out.wind.resize(mesh.positions.size());
        const float height = std::max(frame.top - frame.ground, 1e-6f);
        for (std::size_t k = 0; k < organs.organs(); ++k) {
            Random random(settings.seed * 0x9e3779b97f4a7c15ULL ^ (k + 0x6f7267616eULL));
            const auto phase = static_cast<float>(random.uniform());
            for (std::uint32_t v = organs.first_vertex[k]; v < organs.first_vertex[k + 1]; ++v) {
                const float h =
                    std::clamp((mesh.positions[v].y - frame.ground) / height, 0.0f, 1.0f);
                out.wind[v] = {h * h, 1.0f, phase, 0.0f};
            }
        }
    }
    return out;
}

}  // namespace sylva
