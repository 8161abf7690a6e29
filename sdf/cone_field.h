// The union of many capped cones (the trunk) as one field, evaluated fast: cones are
// binned by their bounding boxes inflated by `margin` (bin_grid.h), so a sample only sees
// the cones near it.
//
// Contract: where the true union distance d is below `margin`, the value is exact;
// elsewhere it is some value >= margin. It stays 1-Lipschitz (a minimum of distances and
// a constant), so meshers may skip empty space: choose margin >= the largest block
// half-diagonal they test.
#pragma once

#include "sdf/bin_grid.h"
#include "sdf/capped_cone.h"

#include <vector>

namespace sylva {

// IQ's quadratic smooth minimum: min(a, b) lowered by up to k/4 where |a - b| < k, exactly
// min(a, b) elsewhere (so culling stays exact), and 1-Lipschitz (a convex gradient blend).
float polynomial_smooth_min(float a, float b, float k);

class ConeField {
public:
    // joint_blend > 0 rounds the joints with polynomial_smooth_min of that radius.
    ConeField(std::vector<CappedCone> cones, float margin, float joint_blend = 0.0f);

    float operator()(const glm::vec3& p) const;

    const std::vector<CappedCone>& cones() const { return cones_; }

private:
    std::vector<CappedCone> cones_;
    float margin_;
    float joint_blend_;
    BinGrid bins_;
};

}  // namespace sylva
