#include "export/mesh_normals.h"

#include <glm/geometric.hpp>

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
