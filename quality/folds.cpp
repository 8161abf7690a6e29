#include "quality/folds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numbers>
#include <vector>

#include "quality/weld.h"

namespace sylva {
namespace {

// One side of an edge: the edge's welded ends in the face's order, the face and the face's
// corner opposite the edge. Sorting by the unordered ends brings the sides of an edge
// together.
struct Side {
    std::uint32_t low, high;  // the ends, smaller first
    std::uint32_t from;       // the end the face's boundary runs from
    std::uint32_t face;
    std::uint32_t far;
};

}  // namespace

Folds measure_folds(const Mesh& mesh, double degrees) {
    const Welding welding = weld_by_position(mesh);
    std::vector<glm::dvec3> points(welding.count);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        points[welding.vertex[v]] = glm::dvec3(mesh.positions[v]);

    std::vector<glm::dvec3> normals(mesh.triangles.size());
    std::vector<Side> sides;
    sides.reserve(3 * mesh.triangles.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        std::array<std::uint32_t, 3> c;
        for (int k = 0; k < 3; ++k) c[k] = welding.vertex[mesh.triangles[f][k]];
        const glm::dvec3 cross =
            glm::cross(points[c[1]] - points[c[0]], points[c[2]] - points[c[0]]);
        const double length = glm::length(cross);
        if (!(length > 0.0)) continue;  // no area (collinear or repeated corners)
        normals[f] = cross / length;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = c[k], b = c[(k + 1) % 3];
            sides.push_back(
                {std::min(a, b), std::max(a, b), a, static_cast<std::uint32_t>(f), c[(k + 2) % 3]});
        }
    }
    std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
        if (a.low != b.low) return a.low < b.low;
        if (a.high != b.high) return a.high < b.high;
        return a.face < b.face;
    });

    // In radians as degrees / 180 * pi: exact for 90, so a right angle is not above 90
    // (acos(0) is pi / 2 rounded, and so is 0.5 * pi; cos(pi / 2) is not 0).
    const double threshold = degrees / 180.0 * std::numbers::pi;
    Folds folds;
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i + 1;
        while (j < sides.size() && sides[j].low == sides[i].low && sides[j].high == sides[i].high)
            ++j;
        if (j - i == 2) {
            const Side& s = sides[i];
            const Side& t = sides[i + 1];
            const double length = glm::length(points[s.high] - points[s.low]);
            folds.interior_length += length;
            ++folds.interior_edges;
            const glm::dvec3& n = normals[s.face];
            const glm::dvec3& m = normals[t.face];
            const bool concave = glm::dot(n, points[t.far] - points[s.low]) > 0.0;
            if (s.from != t.from && concave &&
                std::acos(std::clamp(glm::dot(n, m), -1.0, 1.0)) > threshold) {
                folds.folded_length += length;
                ++folds.folded_edges;
            }
        }
        i = j;
    }
    if (folds.interior_length > 0.0) folds.share = folds.folded_length / folds.interior_length;
    return folds;
}

double concave_fold_share(const Mesh& mesh, double degrees) {
    return measure_folds(mesh, degrees).share;
}

}  // namespace sylva
