// The budget-to-resolution rules: how finely a game mesh of a given triangle budget meshes
// its trunk and crown before the reduction. A grid finer than a budget can show costs
// meshing and reduction time and buys no fidelity; one coarser breaks thin parts apart.
//
// Needs only the template's resolutions and switches (TreeParams) and the budget. Pure
// functions: nothing thrown, safe from any thread. Apart from the pipeline because the
// rules are tuned to what the reduction keeps (sylva-bench-lowpoly --fidelity-only measures
// it), and tree/cost.h and the studio's controls read the same rules.
#pragma once

#include <cstddef>

#include "core/tree_params.h"

namespace sylva {

// The crown's marching-cubes resolution for a game mesh of `budget` trunk + crown
// triangles: the template's, or less when the budget cannot show more (24 at 200, 40 at
// 800, 56 at 3000); 0 (no budget) keeps the template's. The crown is smooth blobs, which a
// coarse grid already draws as well as a small budget can; the trunk keeps more of its
// resolution, since thin branches need it (trunk_resolution_for_budget).
int crown_resolution_for_budget(int resolution, std::size_t budget);

// The trunk's resolution for a game mesh of `budget` triangles: the template's from 800 up
// (0: no budget, the template's too); below 800 the template's times sqrt(budget / 800)
// (half at 200, at least 24 cells). When the crown hides most of the trunk (drop_hidden,
// with a crown), at most one the budget can show, 3 sqrt(budget / 2) cells (1.5 times the
// crown's up to 800: 30 at 200, 60 at 800; 117 at 3000, where the crown has 56), since such
// a trunk ends near its floor of a quarter of the budget
// (elm, fir, maple, spruce, willow, oak, cypress, windswept, ternary).
int trunk_resolution_for_budget(const TreeParams& params, std::size_t budget);
// The budget a template's trunk_resolution is made for (trunk_resolution_for_budget).
inline constexpr std::size_t kTrunkDetailBudget = 800;

}  // namespace sylva
