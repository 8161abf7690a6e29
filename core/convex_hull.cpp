#include "core/convex_hull.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

namespace sylva {
namespace {

struct Face {
    std::array<std::uint32_t, 3> v;
    glm::dvec3 normal;  // unit, outward
    double offset;      // normal . x on the plane
};

Face make_face(const std::vector<glm::dvec3>& p, std::uint32_t a, std::uint32_t b,
               std::uint32_t c) {
    const glm::dvec3 n = glm::cross(p[b] - p[a], p[c] - p[a]);
    const double l = glm::length(n);
    const glm::dvec3 unit = l > 0.0 ? n / l : glm::dvec3(0.0);
    return {{a, b, c}, unit, glm::dot(unit, p[a])};
}

// Every directed edge once and its reverse once, and V - E + F = 2: one closed sphere.
bool is_closed_sphere(const Mesh& hull) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : hull.triangles)
        for (std::size_t k = 0; k < 3; ++k)
            if (!edges.insert({t[k], t[(k + 1) % 3]}).second) return false;
    for (const auto& [a, b] : edges)
        if (!edges.contains({b, a})) return false;
    const auto v = static_cast<long>(hull.positions.size());
    const auto e = static_cast<long>(edges.size() / 2);
    const auto f = static_cast<long>(hull.triangles.size());
    return v - e + f == 2;
}

// The incremental hull, a point counted as seeing a face when it lies more than
// `tolerance` times the rounding margin above its plane.
Mesh incremental_hull(std::span<const glm::vec3> points, double tolerance) {
    std::vector<glm::dvec3> p(points.begin(), points.end());
    if (p.size() < 4) return {};
    double scale = 0.0;
    for (const glm::dvec3& q : p) scale = std::max(scale, glm::length(q - p[0]));
    const double eps = tolerance * (1e-9 * std::max(scale, 1.0) + 1e-7 * scale);

    // A first tetrahedron of far-apart points.
    std::uint32_t i0 = 0, i1 = 0, i2 = 0, i3 = 0;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (p[i].x < p[i0].x) i0 = i;
    double best = -1.0;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (double d = glm::length(p[i] - p[i0]); d > best) best = d, i1 = i;
    best = -1.0;
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (double d = glm::length(glm::cross(p[i] - p[i0], p[i1] - p[i0])); d > best)
            best = d, i2 = i;
    best = -1.0;
    const glm::dvec3 n012 = glm::cross(p[i1] - p[i0], p[i2] - p[i0]);
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (double d = std::abs(glm::dot(p[i] - p[i0], n012)); d > best) best = d, i3 = i;
    if (glm::length(n012) <= eps * scale || best <= eps * glm::length(n012)) return {};

    std::vector<Face> faces;
    if (glm::dot(p[i3] - p[i0], n012) > 0.0) std::swap(i1, i2);  // i3 behind (i0, i1, i2)
    faces.push_back(make_face(p, i0, i1, i2));
    faces.push_back(make_face(p, i0, i3, i1));
    faces.push_back(make_face(p, i1, i3, i2));
    faces.push_back(make_face(p, i2, i3, i0));

    for (std::uint32_t i = 0; i < p.size(); ++i) {
        if (i == i0 || i == i1 || i == i2 || i == i3) continue;
        std::vector<bool> visible(faces.size());
        bool any = false;
        for (std::size_t f = 0; f < faces.size(); ++f) {
            visible[f] = glm::dot(faces[f].normal, p[i]) - faces[f].offset > eps;
            any = any || visible[f];
        }
        if (!any) continue;
        // The horizon: edges of visible faces whose twin lies on a hidden face.
        std::set<std::pair<std::uint32_t, std::uint32_t>> visible_edges;
        for (std::size_t f = 0; f < faces.size(); ++f)
            if (visible[f])
                for (std::size_t k = 0; k < 3; ++k)
                    visible_edges.insert({faces[f].v[k], faces[f].v[(k + 1) % 3]});
        std::vector<Face> kept;
        for (std::size_t f = 0; f < faces.size(); ++f)
            if (!visible[f]) kept.push_back(faces[f]);
        for (std::size_t f = 0; f < faces.size(); ++f) {
            if (!visible[f]) continue;
            for (std::size_t k = 0; k < 3; ++k) {
                const std::uint32_t a = faces[f].v[k], b = faces[f].v[(k + 1) % 3];
                if (!visible_edges.contains({b, a})) kept.push_back(make_face(p, a, b, i));
            }
        }
        faces = std::move(kept);
    }

    Mesh hull;
    std::map<std::uint32_t, std::uint32_t> index;
    for (const Face& f : faces) {
        std::array<std::uint32_t, 3> t{};
        for (std::size_t k = 0; k < 3; ++k) {
            auto [it, added] = index.try_emplace(f.v[k], static_cast<std::uint32_t>(index.size()));
            if (added) hull.positions.push_back(points[f.v[k]]);
            t[k] = it->second;
        }
        hull.triangles.push_back(t);
    }
    return hull;
}

}  // namespace

Mesh convex_hull(std::span<const glm::vec3> points) {
    // A point almost on the planes of several faces can see some of them and not their
    // neighbours, and the faces it adds then share edges three ways (marching-cubes vertices
    // of a crown blob, many on common grid planes, did: 3 of 14,000 random low-budget
    // exports). A wider margin leaves such a point out (the hull moves inwards by at most
    // that margin, 1e-3 of the points' extent at the widest).
    for (const double tolerance : {1.0, 1e2, 1e4}) {
        Mesh hull = incremental_hull(points, tolerance);
        if (hull.triangles.empty() || is_closed_sphere(hull)) return hull;
    }
    return {};
}

Mesh extreme_point_hull(std::span<const glm::vec3> points) {
    if (points.empty()) return {};
    // A Fibonacci sphere of directions.
    std::vector<std::size_t> chosen;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < kHullDirections; ++k) {
        const double y = 1.0 - 2.0 * (k + 0.5) / kHullDirections;
        const double r = std::sqrt(1.0 - y * y);
        const glm::vec3 d(static_cast<float>(r * std::cos(golden * k)), static_cast<float>(y),
                          static_cast<float>(r * std::sin(golden * k)));
        std::size_t best = 0;
        for (std::size_t i = 1; i < points.size(); ++i)
            if (glm::dot(points[i], d) > glm::dot(points[best], d)) best = i;
        chosen.push_back(best);
    }
    std::sort(chosen.begin(), chosen.end());
    chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
    std::vector<glm::vec3> extremes;
    for (std::size_t i : chosen) extremes.push_back(points[i]);
    return convex_hull(extremes);
}

}  // namespace sylva
