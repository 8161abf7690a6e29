// The low-poly stage on a finished tree: trunk and crown reduced to a triangle budget
// (lowpoly/decimate.h), leaves thinned to a budget of their own (tree/leaf_thinning.h),
// LOD chains, and how far a reduction strays from the tree's fine (resolution-200) surface.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lowpoly/decimate.h"
#include "lowpoly/fidelity.h"
#include "tree/crown_hulls.h"
#include "tree/pipeline.h"

namespace sylva {

// A game tree's trunk + crown triangles: the `triangle_budget` default, and where a LOD
// chain starts when no budget is given.
constexpr std::size_t kDefaultTriangleBudget = 800;

// How many triangles a tree keeps. Trunk + crown (the solids) are decimated to `total`;
// leaves are not part of `total` but have a share of their own, `leaves`, which by default
// equals `total`: a default game tree is at most 800 solid + 800 leaf triangles. Leaves are
// thinned out, not decimated (whole leaves are dropped, the rest grown to keep the crown
// as dense; tree/leaf_thinning.h).
struct TreeBudget {
    // Trunk + crown together: one decimation, so the quadric error decides the split
    // (a thin trunk gives up triangles before a round crown does). 800 is a game tree.
    // 0 without part budgets: trunk and crown keep every triangle.
    std::size_t total = kDefaultTriangleBudget;
    // Per part instead: when either is set the parts are reduced separately, a part
    // without its own budget getting what the total leaves (total minus the other's).
    std::optional<std::size_t> trunk = std::nullopt;
    std::optional<std::size_t> crown = std::nullopt;
    // Leaf triangles: at most this many (0: no leaves); unset: `total`, and every leaf
    // when `total` is 0 (no reduction).
    std::optional<std::size_t> leaves = std::nullopt;
    // Whether the crown is reduced as it is or as the hulls of its pieces (CrownShape,
    // core/tree_params.h); unset: the tree's own (Tree::crown_shape, its template's).
    std::optional<CrownShape> crown_shape = std::nullopt;
    // Triangles of the budget per hull when the crown is drawn as hulls; unset: the tree's
    // own (Tree::crown_lump_triangles), else kTrianglesPerHull.
    std::optional<std::size_t> lump_triangles = std::nullopt;
};

// How many hulls `budget` may draw the crown as (tree/crown_hulls.h): 0 for blobs; with
// CrownShape::Hulls, or Automatic (or unset) and a trunk + crown budget (total, or the parts' sum)
// above 0, one per lump_triangles (kTrianglesPerHull unset) of that budget.
// reduce_tree() then takes these or half as many again, whichever keeps closer to the
// crown, and in the automatic mode only for a crown with handles: a crown of blobs that
// touch in rings reduces to spikes and folds, convex hulls to clean facets.
std::size_t crown_hull_count(const TreeBudget& budget);

// The leaf triangles `budget` allows; SIZE_MAX for every leaf.
std::size_t leaf_budget(const TreeBudget& budget);

// The tree's leaves within `budget` triangles (leaf_budget()): the tree's own where they
// fit, else as its leaf style draws them: cards (tree/leaf_cards.h), some of its own
// (tree/leaf_thinning.h) or none; textured cards always (their texture is of many leaves).
// What reduce_tree() and make_lod_chain() give each level.
Mesh game_leaves(const Tree& tree, std::size_t budget);

struct ReducedTree {
    Mesh trunk;  // closed 2-manifolds, empty where the tree has none
    Mesh crown;
    Mesh leaves;                // the tree's leaves thinned to the leaf budget (open)
    std::size_t triangles = 0;  // trunk + crown
    bool within_budget = true;
    int backoffs = 0;                // see DecimateResult
    int handles_cut = 0;             // see DecimateSettings::cut_handles
    std::size_t crossing_pairs = 0;  // see DecimateResult::crossing_pairs
    std::string note;                // empty, or why the budget was missed / what was backed off
};

// Trunk + crown decimated together (or per part) and the leaves thinned, as `budget` says.
// The reduced trunk's lowest point is pinned to the tree's (see make_lod_chain()).
// `settings` supplies the guards, progress and cancel; its max_triangles is ignored.
// Throws what decimate() throws (InputError (core/errors.h) for an open trunk or crown,
// Cancelled).
ReducedTree reduce_tree(const Tree& tree, const TreeBudget& budget,
                        const DecimateSettings& settings = {});

// LOD0 gets `finest` triangles (trunk + crown), each further level half the one before.
std::vector<std::size_t> lod_budgets(std::size_t finest = kDefaultTriangleBudget,
                                     std::size_t levels = 4);
// The same for whole budgets: LOD0 gets `finest` (its total, at least 4), each further level
// half the total and half the leaves of the one before (per-part budgets are not used), all
// with its crown shape.
std::vector<TreeBudget> lod_budgets(const TreeBudget& finest, std::size_t levels);

// A LOD chain, finest first. Level 0 is reduced from the tree, every further level from the
// level before, so no part ever gains triangles from one level to the next (a part that
// would, as when a handle's cap adds some, keeps the level before's mesh). Every level's
// trunk is pinned to the tree's ground: where a reduction lifted or sank the trunk's lowest
// point, the bottom of the trunk is stretched back to it (the rest of the level stays put).
// Leaves are thinned from the tree's for each level, so a coarser level keeps a subset of
// the leaves of a finer one. A level whose crown is drawn as hulls (crown_hull_count())
// makes them from the finest crown, as many as its own budget buys. Errors as
// reduce_tree().
//
// `level0`, when given, is taken as level 0: what reduce_tree(tree, budgets[0]) returned,
// which is what the chain's level 0 is (the studio shows it while the further levels are
// made).
std::vector<ReducedTree> make_lod_chain(const Tree& tree, std::span<const TreeBudget> budgets,
                                        const DecimateSettings& settings = {},
                                        std::optional<ReducedTree> level0 = std::nullopt);

// The tree's fine surface: trunk and crown meshed at `resolution` cells along the longest
// side (fidelity is measured against 200), as one mesh.
Mesh reference_surface(const TreeTemplate& tree, int resolution = 200,
                       const MeshOptions& options = {});

// One-sided distance from trunk + crown to `reference`, in meters and in percent of the
// reference's height (lowpoly/fidelity.h).
Fidelity measure_tree_fidelity(const Mesh& trunk, const Mesh& crown, const Mesh& reference,
                               const FidelitySettings& settings = {});

// The other way round, from `reference` to trunk + crown: what the game mesh lost (a dropped
// branch; twigs hidden inside the crown count too, at the depth they lie), in percent of
// `height` (the forward measure's).
Fidelity measure_tree_loss(const Mesh& trunk, const Mesh& crown, const Mesh& reference,
                           double height);

}  // namespace sylva
