// Points spread uniformly over a mesh's surface (area-weighted), for distance measures.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "core/mesh.h"

namespace sylva {

// `count` points, uniform by area, from a seeded generator of Sylva's own (the same seed
// gives the same points on every platform). Empty for a mesh without area.
std::vector<glm::vec3> sample_surface(const Mesh& mesh, std::size_t count, std::uint64_t seed = 1);

}  // namespace sylva
