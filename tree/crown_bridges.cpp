#include "tree/crown_bridges.h"

#include "tree/crown_merge.h"
#include "tree/field_grid.h"

namespace sylva {

std::vector<CappedCone> crown_bridge_cones(const SphereField& crown, std::size_t budget,
                                           const TreeParams& p, const Box& box) {
    if (budget == 0 || !p.crown_merge) return {};
    const std::vector<Ball>& balls = crown.balls();
    if (count_crown_pieces(balls, 0.0f) * kTrianglesPerCrownPiece <= budget / 2) return {};
    const std::size_t max_pieces = std::max<std::size_t>(1, budget / 2 / kTrianglesPerMergedPiece);
    const float cell = cell_size(box, p.crown_resolution);
    std::vector<CappedCone> cones;
    for (const auto& [i, j] : crown_bridges(balls, max_pieces))
        cones.push_back({balls[i].center, balls[j].center, std::max(balls[i].radius, cell),
                         std::max(balls[j].radius, cell)});
    return cones;
}

}  // namespace sylva
