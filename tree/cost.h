// What a tree will cost before any of it is made: the word's modules, the skeleton's
// segments, the meshing grids' cells, memory and time, from the grammar's growth per step
// (turtle/derivation.h's word_growth) or the growth method's own estimate
// (GrowthMethod::estimate: colonization's points x nodes) and the resolutions. The CLI refuses, and
// the studio asks, above limits that keep one job under about 10 s and 2 GB on two cores.
#pragma once

#include <cstddef>
#include <string>

#include "core/growth.h"
#include "core/tree_template.h"
#include "tree/pipeline.h"

namespace sylva {

struct Cost {
    double modules = 0;    // the derived word, at least (0: not an L-system, or bad grammar)
    double segments = 0;   // the skeleton's segments, at least
    double cells = 0;      // marching-cubes cells of the trunk and crown grids, at most
    double bytes = 0;      // peak memory, roughly
    double seconds = 0;    // wall time on two cores, roughly
    double triangles = 0;  // meshes to reduce (estimate_reduction_cost)
    double handles = 0;    // their handles
    std::string growth;    // what a growth method's estimate counts ("2000 attraction points
                           // x about 900 nodes"), or empty
};

struct CostLimits {
    double max_bytes = 2.0e9;
    double max_seconds = 10.0;
};

// The default limits of a job of many trees (a batch, a forest) as a whole: the same memory,
// and time for a few hundred trees, so a hundred variants need no flag but a billion are
// refused before the first.
inline constexpr CostLimits kManyTreeLimits{2.0e9, 600.0};

// Cheap (no derivation, no grid). `budget` is the trunk + crown triangle budget the meshes
// will be reduced to (0: not reduced), `mesh` false for a skeleton alone. The memory and time
// model is fitted to this project's default template: a rough guide, never below the true
// word and segment counts of an L-system; other growth methods' figures are their own
// estimates (roughly, and GrowthLimits hold them as they grow). A grammar that does not
// parse costs nothing here; generating it reports the error.
Cost estimate_cost(const TreeTemplate& tree, std::size_t budget = 0, bool mesh = true);

// The reduction of a tree already meshed (the slow stage of a game mesh, known only once
// the meshes are): its time from the triangles and handles of what is reduced (where
// branches cross; every one is cut, at a cost that grows with the count), 0 when nothing is
// reduced. A trunk whose branches are prisms is drawn, not reduced. Fitted on the ternary
// tree at generations 6-8 and plain trees to 450,000 triangles.
Cost estimate_reduction_cost(const Tree& tree, std::size_t budget);

// `count` trees of cost `each` made in one job and kept until it writes them (a batch, a
// forest's variants): their time and counts add up; the memory is one tree's peak plus what
// every tree keeps, its finished meshes at `budget` triangles (trunk + crown, leaves and LOD
// levels beside them), or its raw meshes when `budget` is 0.
Cost many_trees_cost(const Cost& each, double count, std::size_t budget);

// "2097152 modules, 2097152 segments, 8.0e+06 cells, about 2.7 GB and 71 s".
std::string cost_text(const Cost& cost);

bool within(const Cost& cost, const CostLimits& limits);

// The same limits for a growth as it goes (MeshOptions::growth_limits, GrowthContext): a
// method that counts its work stops there, saying `how_to_override`, where the estimate
// before it was low.
GrowthLimits growth_limits(const CostLimits& limits, const std::string& how_to_override);

// Throws InputError naming `what` ("this tree", "this batch of 1000000000 trees"), the
// estimate, the limit and `how_to_override` when the cost is over a limit.
void check_cost(const Cost& cost, const CostLimits& limits, const std::string& how_to_override,
                const std::string& what = "this tree");

}  // namespace sylva
