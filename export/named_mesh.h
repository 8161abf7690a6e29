// A part of a model as the exporters see it: a name, a mesh, a colour and whether it is a
// closed solid. The writers (OBJ, glTF, PLY) take lists of these.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "core/mesh.h"

namespace sylva {

struct NamedMesh {
    std::string name;  // the OBJ group and material, the glTF node, mesh and material
    const Mesh* mesh = nullptr;
    glm::vec3 color{0.7f, 0.7f, 0.7f};  // base colour, linear RGB in [0, 1]
    // Solid parts are closed and seen from outside only; open ones (leaves) get
    // double-sided materials where the format has them (glTF).
    bool closed = true;
};

}  // namespace sylva
