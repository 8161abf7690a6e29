#include "sdf/cone_field.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "sdf/point_hash.h"

namespace sylva {

float polynomial_smooth_min(float a, float b, float k) {
    float h = std::max(k - std::abs(a - b), 0.0f) / k;
    return std::min(a, b) - h * h * k * 0.25f;
}

std::vector<CappedCone> merge_coincident_cones(std::vector<CappedCone> cones, float tolerance) {
    if (!(tolerance > 0.0f)) return cones;
    auto finite = [](const glm::vec3& p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    // Both ends of every kept cone, so a copy drawn either way round finds it.
    PointHash ends(tolerance);
    std::vector<CappedCone> out;
    out.reserve(cones.size());
    for (const CappedCone& c : cones) {
        if (!finite(c.a) || !finite(c.b)) {
            out.push_back(c);
            continue;
        }
        std::uint32_t found = UINT32_MAX;
        bool same_way = true;
        ends.for_each_near(c.a, [&](std::uint32_t k) {
            if (found != UINT32_MAX) return;
            const CappedCone& kept = out[k];
            if (glm::distance(kept.a, c.a) <= tolerance && glm::distance(kept.b, c.b) <= tolerance)
                found = k;
            else if (glm::distance(kept.b, c.a) <= tolerance &&
                     glm::distance(kept.a, c.b) <= tolerance)
                found = k, same_way = false;
        });
        if (found == UINT32_MAX) {
            const auto k = static_cast<std::uint32_t>(out.size());
            out.push_back(c);
            ends.insert(c.a, k);
            ends.insert(c.b, k);
            continue;
        }
        CappedCone& kept = out[found];
        kept.ra = std::max(kept.ra, same_way ? c.ra : c.rb);
        kept.rb = std::max(kept.rb, same_way ? c.rb : c.ra);
    }
    return out;
}

ConeField::ConeField(std::vector<CappedCone> cones, float margin, float joint_blend,
                     CancelFlag cancel)
    : cones_(std::move(cones)), margin_(margin), joint_blend_(joint_blend) {
    std::vector<Aabb> boxes;
    boxes.reserve(cones_.size());
    bounds_.reserve(cones_.size());
    prepared_.reserve(cones_.size());
    for (const CappedCone& c : cones_) {
        prepared_.push_back(prepare(c));
        bounds_.push_back(
            {0.5f * (c.a + c.b), 0.5f * glm::length(c.b - c.a) + std::max(c.ra, c.rb)});
        float r = std::max(c.ra, c.rb) + margin_;
        boxes.push_back({glm::min(c.a, c.b) - glm::vec3(r), glm::max(c.a, c.b) + glm::vec3(r)});
    }
    // A bin lists a cone only if some point of the bin can be within the inflation of it.
    const float inflation = margin_ + joint_blend_;
    bins_ = BinGrid(
        boxes, kMinBinInMargins * margin_, 40,
        [&](size_t i, const glm::vec3& centre, float radius) {
            return distance(prepared_[i], centre) < inflation + radius;
        },
        cancel);
}

float ConeField::operator()(const glm::vec3& p) const {
    // A cone whose bounding sphere is at least d + joint_blend away leaves the result
    // unchanged (min, and the polynomial blend is exactly min beyond its radius), so it is
    // skipped without an exact evaluation; the value stays exact.
    auto near = bins_.candidates(p);
    if (near.empty()) return margin_ + bins_.empty_distance(p);
    float d = margin_;
    for (std::uint32_t i : near) {
        const Bound& b = bounds_[i];
        float reach = d + joint_blend_ + b.radius;
        glm::vec3 offset = p - b.center;
        if (reach > 0.0f && glm::dot(offset, offset) >= reach * reach) continue;
        float next = distance(prepared_[i], p);
        d = joint_blend_ > 0.0f ? polynomial_smooth_min(d, next, joint_blend_) : std::min(d, next);
    }
    return std::min(d, margin_);
}

void ConeField::evaluate(std::span<const glm::vec3> points, std::span<float> values) const {
    assert(points.size() == values.size());
    for (std::size_t i = 0; i < points.size(); ++i) values[i] = (*this)(points[i]);
}

}  // namespace sylva
