#include "tree/crown_bridges.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "tree/crown_merge.h"
#include "tree/field_grid.h"
#include "tree/sparse_crown.h"

namespace sylva {
namespace {

constexpr std::size_t kFewestThinPieces = 4;

// A strut's radius at a sphere of `radius` meshed with cells of `cell`. Struts as thick as
// their spheres (at least half a cell, which the grid still draws unbroken between spheres
// it draws) leave open the gaps between blobs that the full-detail crown shows (under a
// tier, inside a curtain). Slender struts (joining the crown into a few pieces) are drawn
// a cell thick: as thin rods they would spend the crown's triangles on themselves and leave
// its blobs as tokens, where a cell-thick strut is a plain slab that also covers the
// branches between the blobs.
float strut_radius(float radius, float cell, bool slender) {
    return std::max(radius, slender ? cell : 0.5f * cell);
}

}  // namespace

bool keeps_sparse_crown_apart(std::size_t budget) {
    return budget / 2 / kTrianglesPerMergedPiece >= kFewestThinPieces;
}

std::vector<CappedCone> crown_bridge_cones(const SphereField& crown, std::size_t budget,
                                           const TreeParams& p, const Box& box) {
    if (budget == 0 || !p.crown_merge) return {};
    const std::vector<Ball>& balls = crown.balls();
    if (count_crown_pieces(balls, 0.0f) * kTrianglesPerCrownPiece <= budget / 2) return {};
    const std::size_t max_pieces = std::max<std::size_t>(1, budget / 2 / kTrianglesPerMergedPiece);
    const float cell = cell_size(box, p.crown_resolution);
    std::vector<CappedCone> cones;
    const auto pairs = crown_bridges(balls, max_pieces);
    // How slender the struts are on average: length over the larger sphere's radius.
    double slenderness = 0.0;
    for (const auto& [i, j] : pairs)
        slenderness += glm::distance(balls[i].center, balls[j].center) /
                       std::max({balls[i].radius, balls[j].radius, 1e-6f});
    // A crown joined into fewer pieces than kFewestThinPieces spans the whole crown with its
    // struts: at such a budget (under 200) a thin strut takes what few triangles there are.
    const bool slender = !pairs.empty() && !keeps_sparse_crown_apart(budget);
    // Slender on average, the struts would lay slabs over the gaps of a sparse crown, which
    // the full-detail tree shows open: its blobs stay apart (tree/sparse_crown.h draws them).
    if (!slender && slenderness > kSparseCrownSpacing * static_cast<double>(pairs.size()))
        return {};
    for (const auto& [i, j] : pairs)
        cones.push_back({balls[i].center, balls[j].center,
                         strut_radius(balls[i].radius, cell, slender),
                         strut_radius(balls[j].radius, cell, slender)});
    return cones;
}

}  // namespace sylva
