#include "export/mesh_normals.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <utility>

namespace sylva {
namespace {

// Twice the area times the unit normal, in double for tiny triangles.
glm::dvec3 area_vector(const Mesh& mesh, const std::array<std::uint32_t, 3>& t) {
    const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
    return glm::cross(b - a, c - a);
}

glm::vec3 unit_or(const glm::dvec3& v, const glm::vec3& fallback) {
    const double length = glm::length(v);
    return length > 0.0 ? glm::vec3(v / length) : fallback;
}

}  // namespace

std::vector<glm::vec3> face_normals(const Mesh& mesh) {
    std::vector<glm::vec3> normals;
    normals.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        normals.push_back(unit_or(area_vector(mesh, t), glm::vec3(0.0f)));
    return normals;
}

std::vector<glm::vec3> vertex_normals(const Mesh& mesh) {
    std::vector<glm::dvec3> sums(mesh.positions.size(), glm::dvec3(0.0));
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 n = area_vector(mesh, t);
        for (std::uint32_t i : t) sums[i] += n;
    }
    std::vector<glm::vec3> normals;
    normals.reserve(sums.size());
    for (const glm::dvec3& s : sums) normals.push_back(unit_or(s, glm::vec3(0.0f, 1.0f, 0.0f)));
    return normals;
}

}  // namespace sylva

namespace sylva {
namespace {

// The angle of triangle `t` at its corner k.
double corner_angle(const Mesh& mesh, const std::array<std::uint32_t, 3>& t, int k) {
    const glm::dvec3 p(mesh.positions[t[static_cast<std::size_t>(k)]]);
    const glm::dvec3 a = glm::dvec3(mesh.positions[t[static_cast<std::size_t>((k + 1) % 3)]]) - p;
    const glm::dvec3 b = glm::dvec3(mesh.positions[t[static_cast<std::size_t>((k + 2) % 3)]]) - p;
    const double la = glm::length(a), lb = glm::length(b);
    if (!(la > 0.0 && lb > 0.0)) return 0.0;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
}

}  // namespace

ShadedMesh smooth_shaded(const Mesh& mesh, float crease_degrees) {
    const std::size_t faces = mesh.triangles.size();
    std::vector<glm::dvec3> normal(faces);
    std::vector<std::array<double, 3>> angle(faces);
    for (std::size_t f = 0; f < faces; ++f) {
        const glm::dvec3 n = area_vector(mesh, mesh.triangles[f]);
        const double length = glm::length(n);
        normal[f] = length > 0.0 ? n / length : glm::dvec3(0.0);
        for (int k = 0; k < 3; ++k)
            angle[f][static_cast<std::size_t>(k)] = corner_angle(mesh, mesh.triangles[f], k);
    }
    // The faces around each vertex, in face order (compressed rows).
    std::vector<std::uint32_t> start(mesh.positions.size() + 1, 0);
    for (const auto& t : mesh.triangles)
        for (std::uint32_t v : t) ++start[v + 1];
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) start[v + 1] += start[v];
    std::vector<std::pair<std::uint32_t, int>> around(start.back());  // face, corner
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t f = 0; f < faces; ++f)
        for (int k = 0; k < 3; ++k)
            around[fill[mesh.triangles[f][static_cast<std::size_t>(k)]]++] = {f, k};

    const double min_cos = std::cos(double(crease_degrees) * std::numbers::pi / 180.0);
    ShadedMesh out;
    out.mesh.positions = mesh.positions;
    out.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
    std::vector<bool> placed(mesh.positions.size(), false);
    // Per vertex, its copies beyond the first: (normal, index).
    std::vector<std::vector<std::pair<glm::vec3, std::uint32_t>>> copies(mesh.positions.size());
    out.mesh.triangles.reserve(faces);
    for (std::uint32_t f = 0; f < faces; ++f) {
        std::array<std::uint32_t, 3> t = mesh.triangles[f];
        for (std::uint32_t& v : t) {
            const bool degenerate = normal[f] == glm::dvec3(0.0);
            glm::dvec3 sum(0.0);
            for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
                const auto [g, k] = around[i];
                if (degenerate || glm::dot(normal[g], normal[f]) >= min_cos)
                    sum += angle[g][static_cast<std::size_t>(k)] * normal[g];
            }
            const glm::vec3 n =
                unit_or(sum, degenerate ? glm::vec3(0, 1, 0) : glm::vec3(normal[f]));
            if (!placed[v]) {
                placed[v] = true;
                out.normals[v] = n;
                continue;
            }
            if (out.normals[v] == n) continue;
            auto& mine = copies[v];
            auto found =
                std::find_if(mine.begin(), mine.end(), [&](const auto& c) { return c.first == n; });
            if (found == mine.end()) {
                mine.push_back({n, static_cast<std::uint32_t>(out.mesh.positions.size())});
                out.mesh.positions.push_back(mesh.positions[v]);
                out.normals.push_back(n);
                found = mine.end() - 1;
            }
            v = found->second;
        }
        out.mesh.triangles.push_back(t);
    }
    return out;
}

}  // namespace sylva
