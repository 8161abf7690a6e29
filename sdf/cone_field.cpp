#include "sdf/cone_field.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace sylva {

float polynomial_smooth_min(float a, float b, float k) {
    float h = std::max(k - std::abs(a - b), 0.0f) / k;
    return std::min(a, b) - h * h * k * 0.25f;
}

ConeField::ConeField(std::vector<CappedCone> cones, float margin, float joint_blend)
    : cones_(std::move(cones)), margin_(margin), joint_blend_(joint_blend) {
    std::vector<Aabb> boxes;
    boxes.reserve(cones_.size());
    for (const CappedCone& c : cones_) {
        float r = std::max(c.ra, c.rb) + margin_;
        boxes.push_back({glm::min(c.a, c.b) - glm::vec3(r), glm::max(c.a, c.b) + glm::vec3(r)});
    }
    bins_ = BinGrid(boxes, margin_);
}

float ConeField::operator()(const glm::vec3& p) const {
    float d = margin_;
    if (joint_blend_ > 0.0f) {
        for (std::uint32_t i : bins_.candidates(p))
            d = polynomial_smooth_min(d, distance(cones_[i], p), joint_blend_);
        return std::min(d, margin_);
    }
    for (std::uint32_t i : bins_.candidates(p)) d = std::min(d, distance(cones_[i], p));
    return d;
}

}  // namespace sylva
