// The low-poly stage on a finished tree: trunk and crown reduced to a triangle budget
// (lowpoly/decimate.h), LOD chains, the parts named and coloured for the exporters, and
// how far a reduction strays from the tree's fine (resolution-200) surface.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lowpoly/decimate.h"
#include "lowpoly/fidelity.h"
#include "tree/pipeline.h"

namespace sylva {

// A game tree's trunk + crown triangles: the `triangle_budget` default, and where a LOD
// chain starts when no budget is given.
constexpr std::size_t kDefaultTriangleBudget = 800;

// How many triangles the solid parts keep (leaves are not reduced).
struct TreeBudget {
    // Trunk + crown together: one decimation, so the quadric error decides the split
    // (a thin trunk gives up triangles before a round crown does). 800 is a game tree.
    std::size_t total = kDefaultTriangleBudget;
    // Per part instead: when either is set the parts are reduced separately, a part
    // without its own budget getting what the total leaves (total minus the other's).
    std::optional<std::size_t> trunk = std::nullopt;
    std::optional<std::size_t> crown = std::nullopt;
};

struct ReducedTree {
    Mesh trunk;  // closed 2-manifolds, empty where the tree has none
    Mesh crown;
    std::size_t triangles = 0;  // trunk + crown
    bool within_budget = true;
    int backoffs = 0;     // see DecimateResult
    int handles_cut = 0;  // see DecimateSettings::cut_handles
    std::string note;     // empty, or why the budget was missed / what was backed off
};

// `settings` supplies the guards, progress and cancel; its max_triangles is ignored.
// Throws what decimate() throws (InputError (core/errors.h) for an open trunk or crown,
// Cancelled).
ReducedTree reduce_tree(const Tree& tree, const TreeBudget& budget,
                        const DecimateSettings& settings = {});

// LOD0 gets `finest` triangles (trunk + crown), each further level half the one before.
std::vector<std::size_t> lod_budgets(std::size_t finest = kDefaultTriangleBudget,
                                     std::size_t levels = 4);

// One reduction per budget, each from the full-resolution tree (not from the level
// before, which would compound the error).
std::vector<ReducedTree> make_lod_chain(const Tree& tree, std::span<const std::size_t> budgets,
                                        const DecimateSettings& settings = {});

// The tree's fine surface: trunk and crown meshed at `resolution` cells along the longest
// side (issue 6 measures against 200), as one mesh.
Mesh reference_surface(const TreeTemplate& tree, int resolution = 200,
                       const MeshOptions& options = {});

// One-sided distance from trunk + crown to `reference`, in meters and in percent of the
// reference's height (lowpoly/fidelity.h).
Fidelity measure_tree_fidelity(const Mesh& trunk, const Mesh& crown, const Mesh& reference,
                               const FidelitySettings& settings = {});

}  // namespace sylva
