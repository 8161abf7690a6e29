// The sampling grid every mesher shares (dense, sparse and OpenVDB), so their vertices lie
// on the same lattice and their surfaces can be compared cell for cell.
#pragma once

#include <array>
#include <glm/vec3.hpp>

#include "marching/mesher.h"

namespace sylva {

struct Grid {
    glm::dvec3 origin{0.0};      // position of node (0, 0, 0)
    double h = 0.0;              // cell size
    std::array<int, 3> nodes{};  // node count per axis (cells + 1)

    glm::dvec3 node(int i, int j, int k) const { return origin + glm::dvec3(i, j, k) * h; }
};

// Cubic cells of size h = longest box side / resolution over the box grown by
// padding_cells * h on every side; on the shorter axes the grid is widened, symmetrically,
// by less than one cell to a whole number of cells.
// Throws InputError when resolution < 1, padding_cells < 0, or the box is empty or not
// finite.
Grid make_grid(const Box& box, const MeshSettings& settings);

}  // namespace sylva
