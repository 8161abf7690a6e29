#include "tree/budget_resolution.h"

#include <algorithm>
#include <cmath>

namespace sylva {
namespace {

// `cells` rounded up, at least 24 (a coarser grid breaks thin parts apart) and at most
// `resolution`: what a budget meshes at instead of the template's resolution.
int capped(int resolution, double cells) {
    return std::min(resolution, std::max(24, static_cast<int>(std::ceil(cells))));
}

// The cells a part needs for its share (half) of `budget` triangles: about sqrt(share)
// vertices along it, and twice that many cells keeps fidelity (40 at 800).
double share_cells(std::size_t budget) {
    return 2.0 * std::sqrt(static_cast<double>(budget) / 2.0);
}

// The crown's cells for `budget` triangles: share_cells up to 800; above, 40 cells times the
// fourth root of budget / 800 (56 at 3000 instead of 78). A crown of blobs is smooth, and at
// such budgets the trunk sets the error: the coarser crown costs the mean error little
// (sylva-bench-lowpoly --budget 3000 --fidelity-only shows it) and the crowned trees export
// faster.
double crown_cells(std::size_t budget) {
    if (budget <= kTrunkDetailBudget) return share_cells(budget);
    return share_cells(kTrunkDetailBudget) *
           std::sqrt(
               std::sqrt(static_cast<double>(budget) / static_cast<double>(kTrunkDetailBudget)));
}

}  // namespace

int crown_resolution_for_budget(int resolution, std::size_t budget) {
    // At 800 the crown's 40 cells keep the mean error close to that of finer crowns and of
    // the template's resolution on every template (sylva-bench-lowpoly --fidelity-only), and
    // the crowned trees export faster.
    return budget == 0 ? resolution : capped(resolution, crown_cells(budget));
}

int trunk_resolution_for_budget(const TreeParams& params, std::size_t budget) {
    int resolution = params.trunk_resolution;
    if (budget == 0) return resolution;
    // Below 800 triangles the template's resolution draws detail no budget keeps: the cells
    // grow with the budget's square root (twice as wide at 200), which costs little fidelity
    // against the template's resolution (sylva-bench-lowpoly --budget 200 shows it).
    if (budget < kTrunkDetailBudget)
        resolution = capped(resolution, std::sqrt(static_cast<double>(budget) /
                                                  static_cast<double>(kTrunkDetailBudget)) *
                                            resolution);
    const bool hidden = params.drop_hidden && params.crown_mesh && params.sphere_diameter > 0.0;
    // With the hidden branches left out, these cells keep the mean error about that of the
    // template's resolution.
    if (hidden) resolution = capped(resolution, 1.5 * share_cells(budget));  // 60 at 800
    return resolution;
}

}  // namespace sylva
