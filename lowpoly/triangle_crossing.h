// Whether two triangles of one surface cut through each other: the test behind the
// reduction's guard against self-intersections (CollapseMesh, lowpoly/quadric_collapse.h).
//
// Triangles of a surface meet where they share corners; they cross when they meet anywhere
// else. Two triangles that share an edge are taken as apart (they can only overlap lying in
// one plane, which the reduction's normal guard keeps from happening). Triangles that share
// one corner cross when the edge of either opposite that corner passes through the other.
// Triangles that share none cross when an edge of either passes through the other. Lying in
// one plane, triangles are taken as apart. Touching counts as crossing (within a tolerance
// of 1e-9 of the triangles' size), so a guard built on it errs on the safe side.
#pragma once

#include <glm/vec3.hpp>

namespace sylva {

// A triangle made ready for many tests: its corners, its unit normal (zero when it has no
// area) and its longest edge.
struct CrossingTriangle {
    glm::dvec3 p[3];
    glm::dvec3 n{0.0};
    double size = 0.0;
};
CrossingTriangle crossing_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Whether a and b cross, `shared` of their corners being the same points (0, 1 or 2; 2:
// apart by definition, see above). With one shared corner, a.p[ka] == b.p[kb] is it.
// Deterministic and free of state: safe from any thread.
bool triangles_cross(const CrossingTriangle& a, const CrossingTriangle& b, int shared, int ka = 0,
                     int kb = 0);

}  // namespace sylva
