// The crown's bridges as fields: when a budget is too small to draw every blob of a crown
// on its own, struts between the nearest blobs (the pairs crown_merge.h picks) become capped
// cones, and the crown and its struts are meshed as one field (BridgedCrown).
//
// Needs the crown's field, the box it is meshed in and the template's crown_merge and
// crown_resolution. Throws nothing of its own (std::bad_alloc aside). crown_bridge_cones
// reads its arguments only; a BridgedCrown is evaluated from any number of threads at once,
// as the meshers do, while its two fields live. Kept apart from the pipeline because it is
// the crown's low-budget shape, not wiring.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "core/box.h"
#include "core/tree_params.h"
#include "sdf/cone_field.h"
#include "sdf/sphere_field.h"

namespace sylva {

// The bridges that let a budget of `budget` trunk + crown triangles draw the crown: with
// crown_merge on and more blobs than half the budget leaves kTrianglesPerCrownPiece each,
// struts between the nearest blobs (crown_merge.h), each a cone from one sphere's centre to
// the other's, at each end as thick as its sphere and at least half a cell (so the grid
// sees it), or at least a cell where the struts join the crown into fewer than four pieces
// (thin, they would take the crown's triangles).
// Empty without a budget, with crown_merge off, when the blobs are few enough, or when the
// struts would be slender (on average longer than kSparseCrownSpacing times the larger
// sphere's radius): a sparse crown, whose gaps the full-detail tree shows open, keeps its
// blobs apart (tree/sparse_crown.h).
std::vector<CappedCone> crown_bridge_cones(const SphereField& crown, std::size_t budget,
                                           const TreeParams& p, const Box& box);

// Whether a budget of `budget` trunk + crown triangles keeps a sparse crown's blobs apart:
// from about 200 on, where the bridges would join the crown into at least four pieces.
// Below, a few of its blobs read less than one slab over them does, and it is bridged.
bool keeps_sparse_crown_apart(std::size_t budget);

// The crown and its bridges as one field: the hard union of two distance bounds, still a
// distance bound, so the sparse meshers may skip space.
struct BridgedCrown {
    const SphereField& crown;
    const ConeField& bridges;
    void evaluate(std::span<const glm::vec3> points, std::span<float> values) const {
        crown.evaluate(points, values);
        std::vector<float> strut(points.size());
        bridges.evaluate(points, strut);
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::min(values[i], strut[i]);
    }
    bool is_distance_bound() const { return crown.is_distance_bound(); }
};

}  // namespace sylva
