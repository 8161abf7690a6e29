// Triangle meshes as plain data, the output of every mesher and the input of every writer.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace sylva {

struct Mesh {
    std::vector<glm::vec3> positions;
    // Counter-clockwise seen from outside: the normal points out of the solid.
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace sylva
