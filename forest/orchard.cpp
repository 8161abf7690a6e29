#include "forest/orchard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>

#include "core/errors.h"

namespace sylva::forest {
namespace {

double segment_distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

double edge_distance(const GroundPolygon& polygon, glm::dvec2 p) {
    double d = std::numeric_limits<double>::max();
    const auto& pts = polygon.points;
    for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++)
        d = std::min(d, segment_distance(p, pts[j], pts[i]));
    return d;
}

void validate(const OrchardSettings& s) {
    if (!(s.row_spacing > 0.0) || !std::isfinite(s.row_spacing))
        throw InputError("--row-spacing must be a positive number of meters");
    if (!(s.tree_spacing > 0.0) || !std::isfinite(s.tree_spacing))
        throw InputError("--tree-spacing must be a positive number of meters");
    if (!(s.margin >= 0.0) || !std::isfinite(s.margin))
        throw InputError("--orchard-margin must be a number of meters, 0 or more");
}

}  // namespace

glm::dvec2 row_direction(const GroundPolygon& polygon) {
    const auto& pts = polygon.points;
    glm::dvec2 best(1.0, 0.0);
    double best_length = 0.0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const glm::dvec2 edge = pts[(i + 1) % pts.size()] - pts[i];
        const double length = glm::length(edge);
        // Ties keep the first edge, so the rows do not depend on rounding.
        if (length > best_length * (1.0 + 1e-9)) best_length = length, best = edge / length;
    }
    return best;
}

glm::dvec2 row_origin(const GroundPolygon& polygon, const OrchardSettings& s) {
    const glm::dvec2 u = row_direction(polygon), v(-u.y, u.x);
    double u0 = std::numeric_limits<double>::max(), u1 = std::numeric_limits<double>::lowest();
    double v0 = u0, v1 = u1;
    for (glm::dvec2 p : polygon.points) {
        u0 = std::min(u0, glm::dot(p, u)), u1 = std::max(u1, glm::dot(p, u));
        v0 = std::min(v0, glm::dot(p, v)), v1 = std::max(v1, glm::dot(p, v));
    }
    // Centre the lattice: the trees nearest the middle sit symmetrically about it.
    const double n_u = std::floor((u1 - u0) / s.tree_spacing);
    const double n_v = std::floor((v1 - v0) / s.row_spacing);
    const double cu = 0.5 * (u0 + u1) - 0.5 * n_u * s.tree_spacing;
    const double cv = 0.5 * (v0 + v1) - 0.5 * n_v * s.row_spacing;
    return cu * u + cv * v;
}

namespace {

// The lattice index ranges of the polygon's rows (i along a row, j across), in doubles.
struct Lattice {
    glm::dvec2 origin{0.0}, u{1.0, 0.0}, v{0.0, 1.0};
    double i0 = 0, i1 = -1, j0 = 0, j1 = -1;
    double points() const { return (i1 - i0 + 1.0) * (j1 - j0 + 1.0); }
};

Lattice lattice(const GroundPolygon& polygon, const OrchardSettings& s) {
    Lattice l;
    l.u = row_direction(polygon);
    l.v = glm::dvec2(-l.u.y, l.u.x);
    l.origin = row_origin(polygon, s);
    double u1 = std::numeric_limits<double>::lowest(), v1 = u1;
    double u0 = std::numeric_limits<double>::max(), v0 = u0;
    for (glm::dvec2 p : polygon.points) {
        u0 = std::min(u0, glm::dot(p - l.origin, l.u));
        u1 = std::max(u1, glm::dot(p - l.origin, l.u));
        v0 = std::min(v0, glm::dot(p - l.origin, l.v));
        v1 = std::max(v1, glm::dot(p - l.origin, l.v));
    }
    l.i0 = std::floor(u0 / s.tree_spacing), l.i1 = std::ceil(u1 / s.tree_spacing);
    l.j0 = std::floor(v0 / s.row_spacing), l.j1 = std::ceil(v1 / s.row_spacing);
    return l;
}

}  // namespace

double orchard_lattice_points(const GroundPolygon& polygon, const OrchardSettings& s) {
    validate(s);
    if (polygon.points.size() < 3) return 0.0;
    const double n = lattice(polygon, s).points();
    return std::isfinite(n) ? n : std::numeric_limits<double>::infinity();
}

std::vector<glm::dvec2> orchard_rows(const GroundPolygon& polygon, const Ground& ground,
                                     const OrchardSettings& s) {
    validate(s);
    std::vector<glm::dvec2> trees;
    if (polygon.points.size() < 3) return trees;
    const Lattice l = lattice(polygon, s);
    const glm::dvec2 origin = l.origin, u = l.u, v = l.v;
    // Compared as a double before the casts: a spacing of 1e-9 m is 1e+20 points.
    if (!(l.points() <= kMaxOrchardLattice)) {
        char figure[160];
        std::snprintf(figure, sizeof figure,
                      "a tree spacing of %g m and a row spacing of %g m would plant up to %.3g "
                      "trees in an orchard polygon; the limit is %.0f",
                      s.tree_spacing, s.row_spacing, l.points(), kMaxOrchardLattice);
        throw InputError(figure);
    }
    const long i0 = static_cast<long>(l.i0), i1 = static_cast<long>(l.i1);
    const long j0 = static_cast<long>(l.j0), j1 = static_cast<long>(l.j1);
    for (long j = j0; j <= j1; ++j)
        for (long i = i0; i <= i1; ++i) {
            const glm::dvec2 p = origin + static_cast<double>(i) * s.tree_spacing * u +
                                 static_cast<double>(j) * s.row_spacing * v;
            if (!contains(polygon, p) || edge_distance(polygon, p) < s.margin) continue;
            bool blocked = false;
            for (const GroundPolygon& other : ground.polygons)
                if (other.cls != "orchard" && other.cls != kForestClass &&
                    other.points.size() >= 3 && contains(other, p))
                    blocked = true;
            if (!blocked) trees.push_back(p);
        }
    return trees;
}

}  // namespace sylva::forest
