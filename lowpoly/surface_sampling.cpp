#include "lowpoly/surface_sampling.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/random.h"

namespace sylva {
std::vector<glm::vec3> sample_surface(const Mesh& mesh, std::size_t count, std::uint64_t seed) {
    std::vector<double> cumulative;
    cumulative.reserve(mesh.triangles.size());
    double total = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        total += 0.5 * glm::length(glm::cross(b - a, c - a));
        cumulative.push_back(total);
    }
    std::vector<glm::vec3> points;
    if (!(total > 0.0)) return points;
    points.reserve(count);
    Random rng(seed);
    for (std::size_t i = 0; i < count; ++i) {
        const double pick = rng.uniform() * total;
        std::size_t k = static_cast<std::size_t>(
            std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
        k = std::min(k, cumulative.size() - 1);
        const auto& t = mesh.triangles[k];
        // Uniform on the triangle: the square-root warp of two uniforms.
        const double r1 = std::sqrt(rng.uniform()), r2 = rng.uniform();
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        points.emplace_back((1.0 - r1) * a + r1 * (1.0 - r2) * b + r1 * r2 * c);
    }
    return points;
}

}  // namespace sylva
