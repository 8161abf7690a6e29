// A uniform grid of indexed points for radius queries: the spatial index that replaces
// Liebemann's (2017) brute-force "nearest node for every attraction point" (6.1.1). Positions
// outside the grid's box are clamped into its border cells, which keeps every query exact
// (clamping never moves a point out of the cells a query ball covers), only slower there.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "core/box.h"

namespace sylva {

class CellGrid {
  public:
    // Cells about `cell` wide over `box`; wider when that would make too many cells.
    CellGrid(const Box& box, float cell) : origin_(box.min) {
        const glm::vec3 extent = glm::max(box.max - box.min, glm::vec3(1e-6f));
        cell = std::max(cell, 1e-6f);
        // At most ~2 million cells: memory stays small whatever the radius.
        const float volume_cells = (extent.x / cell) * (extent.y / cell) * (extent.z / cell);
        if (volume_cells > 2e6f) cell *= std::cbrt(volume_cells / 2e6f);
        inverse_ = 1.0f / cell;
        for (int k = 0; k < 3; ++k)
            dims_[k] = std::max(1, static_cast<int>(std::ceil(extent[k] * inverse_)));
        cells_.resize(static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2]);
    }

    void insert(int index, const glm::vec3& p) { cells_[cell_index(cell_of(p))].push_back(index); }

    // Calls visit(index) for every index in a cell that the ball (p, radius) overlaps: a
    // superset of the indices within `radius`, in a fixed order.
    template <class Visit>
    void for_each_near(const glm::vec3& p, float radius, Visit&& visit) const {
        const glm::ivec3 lo = cell_of(p - glm::vec3(radius));
        const glm::ivec3 hi = cell_of(p + glm::vec3(radius));
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    for (int index : cells_[cell_index({x, y, z})]) visit(index);
    }

    // Like for_each_near, but keeps only the indices for which keep(index) returns true:
    // how dead attraction points leave the grid, so later queries skip them.
    template <class Keep>
    void filter_near(const glm::vec3& p, float radius, Keep&& keep) {
        const glm::ivec3 lo = cell_of(p - glm::vec3(radius));
        const glm::ivec3 hi = cell_of(p + glm::vec3(radius));
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    std::vector<int>& cell = cells_[cell_index({x, y, z})];
                    // Stable, so the visiting order (and so the result) stays fixed.
                    cell.erase(std::remove_if(cell.begin(), cell.end(),
                                              [&](int index) { return !keep(index); }),
                               cell.end());
                }
    }

  private:
    glm::ivec3 cell_of(const glm::vec3& p) const {
        glm::ivec3 c;
        for (int k = 0; k < 3; ++k) {
            const float f = std::floor((p[k] - origin_[k]) * inverse_);
            c[k] = static_cast<int>(std::clamp(f, 0.0f, static_cast<float>(dims_[k] - 1)));
        }
        return c;
    }
    size_t cell_index(const glm::ivec3& c) const {
        return (static_cast<size_t>(c.z) * dims_[1] + c.y) * dims_[0] + c.x;
    }

    glm::vec3 origin_;
    float inverse_ = 1.0f;
    int dims_[3] = {1, 1, 1};
    std::vector<std::vector<int>> cells_;
};

}  // namespace sylva
