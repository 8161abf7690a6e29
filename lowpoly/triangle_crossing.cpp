#include "lowpoly/triangle_crossing.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace sylva {
namespace {

// Six times the signed volume of the tetrahedron (a, b, c, d).
double orient(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    return glm::dot(glm::cross(b - a, c - a), d - a);
}

// The segment p-q, whose ends lie at heights dp and dq over triangle t's plane, meets t
// (touching included: within `eps` of height, `eps3` of volume).
bool segment_meets(const glm::dvec3& p, const glm::dvec3& q, double dp, double dq,
                   const CrossingTriangle& t, double eps, double eps3) {
    if ((dp > eps && dq > eps) || (dp < -eps && dq < -eps)) return false;  // one side
    if (std::abs(dp) <= eps && std::abs(dq) <= eps) return false;          // in its plane
    // Through the triangle's plane: inside when the segment's line passes each edge the
    // same way round.
    const double e0 = orient(p, q, t.p[0], t.p[1]), e1 = orient(p, q, t.p[1], t.p[2]),
                 e2 = orient(p, q, t.p[2], t.p[0]);
    return (e0 >= -eps3 && e1 >= -eps3 && e2 >= -eps3) || (e0 <= eps3 && e1 <= eps3 && e2 <= eps3);
}

bool one_side(const double (&d)[3], double eps) {
    return (d[0] > eps && d[1] > eps && d[2] > eps) || (d[0] < -eps && d[1] < -eps && d[2] < -eps);
}

}  // namespace

CrossingTriangle crossing_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    CrossingTriangle t;
    t.p[0] = a, t.p[1] = b, t.p[2] = c;
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    if (length > 0.0) t.n = n / length;
    t.size = std::sqrt(
        std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)}));
    return t;
}

bool triangles_cross(const CrossingTriangle& a, const CrossingTriangle& b, int shared, int ka,
                     int kb) {
    if (shared >= 2) return false;
    const double size = std::max(a.size, b.size);
    const double eps = 1e-9 * size, eps3 = eps * size * size;
    // Each corner's height over the other's plane.
    double da[3], db[3];
    for (int i = 0; i < 3; ++i) {
        da[i] = glm::dot(b.n, a.p[i] - b.p[0]);
        db[i] = glm::dot(a.n, b.p[i] - a.p[0]);
    }
    if (shared == 1) {  // the edges opposite the shared corner
        const int a1 = (ka + 1) % 3, a2 = (ka + 2) % 3, b1 = (kb + 1) % 3, b2 = (kb + 2) % 3;
        return segment_meets(a.p[a1], a.p[a2], da[a1], da[a2], b, eps, eps3) ||
               segment_meets(b.p[b1], b.p[b2], db[b1], db[b2], a, eps, eps3);
    }
    if (one_side(da, eps) || one_side(db, eps)) return false;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if (segment_meets(a.p[i], a.p[j], da[i], da[j], b, eps, eps3) ||
            segment_meets(b.p[i], b.p[j], db[i], db[j], a, eps, eps3))
            return true;
    }
    return false;
}

}  // namespace sylva
