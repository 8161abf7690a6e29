#include "marching/grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.h"

namespace sylva {

Grid make_grid(const Box& box, const MeshSettings& settings) {
    if (settings.resolution < 1) {
        throw InputError("marching_cubes: resolution must be at least 1, got " +
                         std::to_string(settings.resolution));
    }
    if (settings.padding_cells < 0) {
        throw InputError("marching_cubes: padding_cells must not be negative, got " +
                         std::to_string(settings.padding_cells));
    }
    const glm::dvec3 lo(box.min);
    const glm::dvec3 hi(box.max);
    double longest = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(lo[a]) || !std::isfinite(hi[a]) || hi[a] < lo[a]) {
            throw InputError("marching_cubes: box must be finite with min <= max on every axis");
        }
        longest = std::max(longest, hi[a] - lo[a]);
    }
    if (!(longest > 0.0)) throw InputError("marching_cubes: box is empty");

    Grid grid;
    grid.h = longest / settings.resolution;
    for (int a = 0; a < 3; ++a) {
        const double extent = hi[a] - lo[a] + 2.0 * settings.padding_cells * grid.h;
        // The tolerance keeps the longest axis, whose extent is a whole number of cells up
        // to rounding, from gaining a spurious cell.
        const double cells = std::max(1.0, std::ceil(extent / grid.h - 1e-6));
        if (cells + 1.0 > double(std::numeric_limits<int>::max())) {
            throw InputError("marching_cubes: grid too large");
        }
        grid.nodes[a] = int(cells) + 1;
        // Centred, so the extra fraction of a cell on the shorter axes is split evenly.
        grid.origin[a] = 0.5 * (lo[a] + hi[a]) - 0.5 * cells * grid.h;
    }
    return grid;
}

}  // namespace sylva
