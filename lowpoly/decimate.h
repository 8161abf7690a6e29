// Low poly for real: quadric error decimation (Garland-Heckbert) of closed meshes down to
// a triangle budget, keeping every part a closed, consistently oriented 2-manifold.
//
// A greedy loop of halfedge collapses on flat arrays (lowpoly/quadric_collapse.h: the
// rules of OpenMesh's DecimaterT with its quadric module, the link condition, guards
// against fold-overs and slivers), quadric-optimal vertex placement at the end, and handle
// cutting (lowpoly/handle_cutting.h) for budgets below what the topology allows.
//
// Speed: about 1 us per input triangle on one core when no handle needs cutting (the bulk in
// sorted passes, the last collapses from a heap). Both cores: each part is reduced on a
// core of its own, a part with most of the triangles in two lanes of its connected
// components (a game mesh's trunk is meshed in pieces for this, tree/trunk_pieces.h), and the
// shared order of the parts' last collapses runs in parallel up to an error bound.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/cancel.h"
#include "core/mesh.h"

namespace sylva {

// The fewest foot vertices a piece keeps (DecimateSettings::foot_height): a hexagon.
inline constexpr std::size_t kMinFootVertices = 6;

// A part with at least this many triangles (and more than half of all) is reduced in two
// lanes of its connected components, one per core; below it a part takes a few milliseconds
// and splitting would not pay. A caller that meshes a part in pieces for the lanes (the
// pipeline's trunk) needs no pieces below it.
inline constexpr std::size_t kLaneSplitTriangles = 8000;

struct DecimateSettings {
    // Triangle budget over all the parts reduced together. They share it: one priority
    // queue of collapses ordered by quadric error decides where the triangles go, so a
    // thin trunk gives up triangles before a round crown does. For a budget per part,
    // call decimate() once per part.
    std::size_t max_triangles = 800;
    // Guard against fold-overs: no collapse may turn a remaining triangle's normal by
    // more than this many degrees (OpenMesh's normal-flip module uses 90).
    double max_normal_turn_degrees = 75.0;
    // When the budget is below what the topology allows (every handle, where branches
    // cross, pins about a dozen triangles), cut handles along their shortest loops and cap
    // them (lowpoly/handle_cutting.h), then reduce again. Still closed and manifold; the
    // shape changes by a branch cross-section per cut.
    bool cut_handles = true;
    // After the collapses, move each vertex to the minimum of its accumulated quadric
    // (guarded like a collapse): facets then straddle the input surface instead of
    // lying inside it, which roughly halves the mean distance at game budgets.
    bool relocate_vertices = true;
    // Collapse order. true: a vertex waits in the queue by its cheapest collapse by error,
    // and the legality tests (link condition, guards) run when it reaches the front. false:
    // after each collapse its neighbours are tested at once, as OpenMesh's decimater does
    // (where no handle is cut, the output then matched the OpenMesh-based reducer this one
    // replaced, in the checks made), at about 1.7x the run time. Lazy legality sees legality as it
    // is when a collapse is made rather than when it was queued; mean errors stay within a few
    // percent either way.
    bool lazy_legality = true;
    // The bulk of the collapses in passes (lowpoly/quadric_collapse.h, as meshoptimizer
    // orders them): each pass sorts the vertices by their cheapest collapse once and makes,
    // cheapest first, those up to 1.2x the error of the last collapse it wants (half of those
    // still needed), each vertex once; the heap orders the collapses one at a time below
    // twice the count asked for (and below 4096 triangles). The mean error stays within a
    // few percent of the heap's. false: the heap all the way (the order before passes; the
    // bulk of a ternary's trunk then takes 1.4x as long).
    bool fast_passes = true;
    // After the collapses (and relocation), flip edges where two faces fold inwards
    // sharper than a right angle (CollapseMesh::unfold(), lowpoly/quadric_collapse.h): a
    // reduced crown of many spheres otherwise reads as a ball of spikes.
    bool unfold = true;
    // No two faces of a piece cross: from twice the budget on (before, faces are too small
    // to reach through the surface), a collapse, relocation or flip that would make faces
    // cross is not made (lowpoly/triangle_crossing.h), checked against the faces near it in
    // a grid (lowpoly/face_grid.h). A branch folded through itself or its parent reads as a
    // crease or a hole. Where only crossing collapses are left above the budget (twigs
    // packed closer than a facet), those are made, cheapest first, and the result says so
    // (DecimateResult::crossing_pairs). Faces of different pieces may cross. Handle
    // cutting's reductions of the cut parts run without it.
    bool keep_apart = true;
    // Count the pairs of faces of one piece that cross in the result
    // (DecimateResult::crossing_pairs; about a microsecond per face left).
    bool count_crossings = true;
    // In the shared order, a part with more triangles than this never goes below it: its
    // collapses stop there and the other parts take the rest of the budget (0: no floor).
    // reduce_tree() keeps trunk and crown at a quarter of the budget each this way, so
    // neither shrinks to a token solid beside the other.
    std::size_t part_floor = 0;
    // Vertices at or below this height (Y) are the foot, where the model stands: no
    // collapse lifts a foot vertex off it (nor does relocation), and each piece keeps at
    // least kMinFootVertices of them. Without it a thin trunk's base ring, cheap to
    // collapse, ends in a point and the tree stands on a needle. -inf: no foot.
    float foot_height = -std::numeric_limits<float>::infinity();
    // Called with the finished fraction (0..1) from the calling thread.
    std::function<void(float)> progress;
    // Polled every few hundred collapses; when it becomes true, decimate() throws
    // Cancelled.
    CancelFlag cancel = nullptr;
};

struct DecimateResult {
    std::vector<Mesh> parts;     // in the order given; each a closed 2-manifold
    std::size_t triangles = 0;   // over all parts
    bool within_budget = false;  // triangles <= max_triangles
    // How often a reduction was redone with fewer collapses because a part failed
    // check_topology (core/mesh_checks.h). 0 in every case seen so far: the link
    // condition and the guards keep the manifold; the back-off is the safety net.
    int backoffs = 0;
    int handles_cut = 0;  // see DecimateSettings::cut_handles
    // The pairs of faces of one piece that cross (counted on the result:
    // CollapseMesh::crossing_pairs()), where the budget could only be reached with
    // collapses that make them cross or the collapses before the guard started did; the
    // note says so. 0 without count_crossings (not counted).
    std::size_t crossing_pairs = 0;
    // Empty, or a sentence for people: why the budget was missed, or what was backed off.
    std::string note;
};

// Reduces the parts together to settings.max_triangles (or as close as the guards allow:
// each closed piece needs at least 4 triangles, and handles need more).
//
// Preconditions: every non-empty part is a closed 2-manifold by check_topology (triangles of
// zero area allowed: they go first); otherwise throws InputError (core/errors.h) naming the
// part and what is wrong. Empty parts stay empty.
// Guarantee: every returned part is a closed 2-manifold with the input's orientation and no
// piece turned inside out (checked with check_topology, and component_volumes: no more
// components without positive volume than the input had, which are its inner shells, see
// lowpoly/inner_shells.h); when a reduction breaks that, it is redone with fewer
// collapses, down to returning the input. Connected components never vanish or merge;
// handles are kept unless cut_handles had to cut some (then result.handles_cut > 0).
// Deterministic: the same input gives the same output. Not thread-safe on shared settings
// callbacks; otherwise reentrant (no global state).
DecimateResult decimate(std::span<const Mesh* const> parts, const DecimateSettings& settings);

// One mesh: the same, with result.parts.size() == 1.
DecimateResult decimate(const Mesh& mesh, const DecimateSettings& settings);

}  // namespace sylva
