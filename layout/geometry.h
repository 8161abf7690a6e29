// Small exact-enough 2D predicates the layout module shares: polygon area, segment contact
// (crossing or touching within eps), point-to-segment distance, point in polygon.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <vector>

namespace sylva::layout {

inline double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

inline double signed_area(const std::vector<glm::dvec2>& pts) {
    double a = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) a += cross(pts[i], pts[(i + 1) % pts.size()]);
    return 0.5 * a;
}

inline double point_segment_distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    double t = len2 > 0 ? glm::dot(p - a, ab) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return glm::length(p - (a + t * ab));
}

// True when segments ab and cd cross or come within eps of each other.
inline bool segments_touch(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d, double eps) {
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    return point_segment_distance(c, a, b) <= eps || point_segment_distance(d, a, b) <= eps ||
           point_segment_distance(a, c, d) <= eps || point_segment_distance(b, c, d) <= eps;
}

// 1 strictly inside, 0 on the boundary (within eps), -1 outside.
inline int point_in_polygon(glm::dvec2 p, const std::vector<glm::dvec2>& pts, double eps) {
    const std::size_t n = pts.size();
    bool inside = false;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        if (point_segment_distance(p, pts[j], pts[i]) <= eps) return 0;
        if ((pts[i].y > p.y) != (pts[j].y > p.y) &&
            p.x < (pts[j].x - pts[i].x) * (p.y - pts[i].y) / (pts[j].y - pts[i].y) + pts[i].x)
            inside = !inside;
    }
    return inside ? 1 : -1;
}

}  // namespace sylva::layout
