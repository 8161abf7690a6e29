// Wavefront OBJ export: one group per part, Y up, meters. Written atomically.
#pragma once

#include "marching/mesh.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace sylva {

struct NamedMesh {
    std::string name;  // becomes the OBJ group ("trunk", "crown", "leaves")
    const Mesh* mesh = nullptr;
};

void write_obj(std::ostream& out, const std::vector<NamedMesh>& parts);

// Throws IoError naming the path when it cannot be written; never leaves a partial file.
void write_obj(const std::filesystem::path& path, const std::vector<NamedMesh>& parts);

}  // namespace sylva
