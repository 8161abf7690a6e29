// The union of many capped cones as one field, evaluated fast: cones are binned into a
// uniform grid by their bounding boxes inflated by `margin`, so a sample only sees the
// cones near it.
//
// Contract: where the true union distance d is below `margin`, the value is exact; elsewhere
// it is some value >= margin (never wrong in sign). Marching cubes only needs exact values
// within a cell of the surface, so margin = 2 cells suffices.
#pragma once

#include "sdf/capped_cone.h"

#include <cstdint>
#include <vector>

namespace sylva {

class ConeField {
public:
    ConeField(std::vector<CappedCone> cones, float margin);

    float operator()(const glm::vec3& p) const;

    const std::vector<CappedCone>& cones() const { return cones_; }

private:
    std::vector<CappedCone> cones_;
    float margin_;
    glm::vec3 origin_{0.0f};
    float bin_size_ = 1.0f;
    glm::ivec3 dims_{0};
    std::vector<std::uint32_t> bin_start_;  // CSR: cones of bin b are
    std::vector<std::uint32_t> bin_cones_;  // bin_cones_[bin_start_[b] .. bin_start_[b+1])
};

}  // namespace sylva
