#include "sdf/sphere_field.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>

#include "sdf/point_hash.h"

namespace sylva {

float distance(const Ball& ball, const glm::vec3& p) {
    return glm::length(p - ball.center) - ball.radius;
}

std::vector<Ball> merge_coincident_balls(std::vector<Ball> balls, float tolerance) {
    if (!(tolerance > 0.0f)) return balls;
    PointHash centres(tolerance);
    std::vector<Ball> out;
    out.reserve(balls.size());
    for (const Ball& b : balls) {
        std::uint32_t found = UINT32_MAX;
        centres.for_each_near(b.center, [&](std::uint32_t k) {
            if (found == UINT32_MAX && glm::distance(out[k].center, b.center) <= tolerance)
                found = k;
        });
        if (found != UINT32_MAX) {
            out[found].radius = std::max(out[found].radius, b.radius);
            continue;
        }
        centres.insert(b.center, static_cast<std::uint32_t>(out.size()));
        out.push_back(b);
    }
    return out;
}

float root_smooth_min(float a, float b, float k) {
    float x = a - b;
    return 0.5f * (a + b - std::sqrt(x * x + k * k));
}

float pasko_savchenko_union(float a, float b, float alpha) {
    return (a + b - std::sqrt(std::max(a * a + b * b - 2.0f * alpha * a * b, 0.0f))) /
           (1.0f + alpha);
}

SphereField::SphereField(std::vector<Ball> balls, float blend, float margin, SphereBlend kind)
    : balls_(std::move(balls)), blend_(blend), margin_(margin), kind_(kind) {
    std::vector<Aabb> boxes;
    boxes.reserve(balls_.size());
    for (const Ball& b : balls_) {
        glm::vec3 r(b.radius + margin_);
        boxes.push_back({b.center - r, b.center + r});
    }
    bins_ = BinGrid(boxes, kMinBinInMargins * margin_, 40,
                    [&](size_t i, std::span<const glm::vec3> centres, float radius,
                        std::span<std::uint8_t> keep) {
                        for (std::size_t j = 0; j < centres.size(); ++j)
                            keep[j] = distance(balls_[i], centres[j]) < margin_ + radius;
                    });
}

float SphereField::operator()(const glm::vec3& p) const {
    // The fold starts at the margin (values near it may blend with it, which the contract
    // allows) and skips spheres too far to matter: with the local blend, a sphere at least
    // 4 k beyond the running value and beyond the nearest sphere so far leaves both
    // unchanged, so the value stays exact.
    auto near = bins_.candidates(p);
    if (near.empty()) return margin_ + bins_.empty_distance(p);
    if (kind_ == SphereBlend::PaskoSavchenko) {
        float d = margin_;
        for (std::uint32_t i : near) d = pasko_savchenko_union(d, distance(balls_[i], p), blend_);
        return std::min(d, margin_);
    }
    float d = margin_;
    float nearest = margin_;
    for (std::uint32_t i : near) {
        const Ball& ball = balls_[i];
        glm::vec3 offset = p - ball.center;
        float reach = std::max(d + 4.0f * blend_, nearest) + ball.radius;
        if (reach > 0.0f && glm::dot(offset, offset) >= reach * reach) continue;
        float next = std::sqrt(glm::dot(offset, offset)) - ball.radius;
        nearest = std::min(nearest, next);
        d = blend_ > 0.0f ? local_root_smooth_min(d, next, blend_) : std::min(d, next);
    }
    return std::min(std::max(d, nearest - 0.5f * blend_), margin_);
}

void SphereField::evaluate(std::span<const glm::vec3> points, std::span<float> values) const {
    assert(points.size() == values.size());
    for (std::size_t i = 0; i < points.size(); ++i) values[i] = (*this)(points[i]);
}

}  // namespace sylva
