// Normals for the exporters: one per triangle (flat shading) or one per vertex (smooth),
// smooth ones split where the surface creases so the low-poly facets stay visible.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "core/mesh.h"

namespace sylva {

// Unit normal of each triangle (counter-clockwise = outward); zero for a degenerate one.
std::vector<glm::vec3> face_normals(const Mesh& mesh);

// Unit normal of each vertex: the area-weighted mean of the normals of the triangles
// around it; +Y for a vertex without area around it (so the output is always unit). No
// crease: on a reduced tree a vertex can get a normal far from some of its faces; the
// exporters use smooth_shaded().
std::vector<glm::vec3> vertex_normals(const Mesh& mesh);

// Faces that meet at more than this many degrees are shaded apart: the edge stays sharp.
constexpr float kDefaultCreaseDegrees = 60.0f;

// A mesh with one unit normal per vertex (positions may repeat where a vertex was split).
struct ShadedMesh {
    Mesh mesh;
    std::vector<glm::vec3> normals;
};

// Smooth normals with a crease. Each corner of a triangle gets the angle-weighted mean of
// the unit normals of the triangles around its vertex that lie within `crease_degrees` of
// its own triangle (its own included), so every normal stays within 90 degrees of every
// face that uses it (for a crease below 90) and follows the winding. A vertex whose corners
// disagree is split, one copy per distinct normal: vertex i keeps index i for its first
// normal, the copies are appended. A degenerate triangle takes the mean of all triangles
// around the vertex (+Y when there is none). Same input, same output.
ShadedMesh smooth_shaded(const Mesh& mesh, float crease_degrees = kDefaultCreaseDegrees);

}  // namespace sylva
