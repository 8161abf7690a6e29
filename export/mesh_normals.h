// Normals for the exporters: one per triangle (flat shading) or one per vertex (smooth).
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "core/mesh.h"

namespace sylva {

// Unit normal of each triangle (counter-clockwise = outward); zero for a degenerate one.
std::vector<glm::vec3> face_normals(const Mesh& mesh);

// Unit normal of each vertex: the area-weighted mean of the normals of the triangles
// around it; +Y for a vertex without area around it (so the output is always unit).
std::vector<glm::vec3> vertex_normals(const Mesh& mesh);

}  // namespace sylva
