// The union of many capped cones (the trunk) as one field, evaluated fast: cones are
// binned by their bounding boxes inflated by `margin` (bin_grid.h), so a sample only sees
// the cones near it.
//
// Contract: where the true union distance d is below `margin`, the value is exact;
// elsewhere it is a value between margin and d: a lower bound of the distance, so meshers
// may skip any block whose centre value exceeds its half-diagonal. Far from every cone the
// bound comes from a distance transform over the bins, so big empty blocks are skipped
// without visiting a single cone.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sdf/bin_grid.h"
#include "sdf/capped_cone.h"

namespace sylva {

// IQ's quadratic smooth minimum: min(a, b) lowered by up to k/4 where |a - b| < k, exactly
// min(a, b) elsewhere (so culling stays exact), and 1-Lipschitz (a convex gradient blend).
float polynomial_smooth_min(float a, float b, float k);

// The cones with near-coincident duplicates merged: a cone whose two ends each lie within
// `tolerance` of the ends of an earlier kept cone (either way round) is folded into it,
// which takes the larger radius at each end; the union moves by at most `tolerance`. A field
// over thousands of copies of one segment (`F -> [F][F][F][F]`, or the same with tiny
// turns) would otherwise list them all in one bin and visit each at every sample: quadratic
// in the copies. Order of first appearance is kept, so the result is deterministic. Cones
// with a non-finite end are kept as they are.
std::vector<CappedCone> merge_coincident_cones(std::vector<CappedCone> cones, float tolerance);

class ConeField {
  public:
    // joint_blend > 0 rounds the joints with polynomial_smooth_min of that radius. Throws
    // Cancelled once `cancel` is set while the bins are built.
    ConeField(std::vector<CappedCone> cones, float margin, float joint_blend = 0.0f,
              CancelFlag cancel = nullptr);

    float operator()(const glm::vec3& p) const;
    // values[i] = (*this)(points[i]) for spans of the same size: one call per batch of
    // points (as a mesher samples them) rather than one per point. Thread-safe.
    void evaluate(std::span<const glm::vec3> points, std::span<float> values) const;

    const std::vector<CappedCone>& cones() const { return cones_; }

  private:
    // A cone as its samples read it, in one cache line: its bounding sphere (a cheap lower
    // bound on its distance lets a sample skip cones that cannot change the result) and its
    // terms prepared once for its many samples, as four groups of four floats, so that four
    // cones load and transpose into the lanes of a vector.
    struct alignas(16) Packed {
        glm::vec3 center{0.0f};
        float radius = 0.0f;
        PreparedCone cone;
        float unused = 0.0f;
    };
    // The hard union (no joint blend) of the cones `near` at p, four at a time.
    float hard_union(const glm::vec3& p, std::span<const std::uint32_t> near) const;

    std::vector<CappedCone> cones_;
    std::vector<Packed> packed_;  // one per cone of cones_
    float margin_;
    float joint_blend_;
    BinGrid bins_;
};

}  // namespace sylva
