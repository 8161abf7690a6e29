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

float local_root_smooth_min(float a, float b, float k) {
    float x = std::abs(a - b);
    if (x >= 4.0f * k) return std::min(a, b);
    // Smoothstep from 1 at 2k to 0 at 4k: its slope (at most 0.75 / k) keeps the blend
    // 1-Lipschitz (d/dx sqrt(x^2 + w^2) = (x + w w') / sqrt(...) stays within [-1, 1]).
    float t = std::clamp((x - 2.0f * k) / (2.0f * k), 0.0f, 1.0f);
    float w = k * (1.0f - t * t * (3.0f - 2.0f * t));
    return 0.5f * (a + b - std::sqrt(x * x + w * w));
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
    bins_ =
        BinGrid(boxes, margin_ / 2.0f, 40, [&](size_t i, const glm::vec3& centre, float radius) {
            return distance(balls_[i], centre) < margin_ + radius;
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
    if (!(blend_ > 0.0f)) {
        for (std::uint32_t i : near) {
            const Ball& ball = balls_[i];
            glm::vec3 offset = p - ball.center;
            float reach = std::max(d + 4.0f * blend_, nearest) + ball.radius;
            if (reach > 0.0f && glm::dot(offset, offset) >= reach * reach) continue;
            float next = std::sqrt(glm::dot(offset, offset)) - ball.radius;
            nearest = std::min(nearest, next);
            d = std::min(d, next);
        }
        return std::min(std::max(d, nearest - 0.5f * blend_), margin_);
    }
    // local_root_smooth_min inlined, with what depends on k alone taken out of the loop (the
    // products by 2 and 4 are exact) and the fade skipped below 2 k, where it is k exactly:
    // the same operations on the same values, so the same bits.
    const float k = blend_, two_k = 2.0f * k, four_k = 4.0f * k, kk = k * k;
    for (std::uint32_t i : near) {
        const Ball& ball = balls_[i];
        glm::vec3 offset = p - ball.center;
        float reach = std::max(d + four_k, nearest) + ball.radius;
        if (reach > 0.0f && glm::dot(offset, offset) >= reach * reach) continue;
        float next = std::sqrt(glm::dot(offset, offset)) - ball.radius;
        nearest = std::min(nearest, next);
        float x = std::abs(d - next);
        if (x >= four_k) {
            d = std::min(d, next);
            continue;
        }
        float ww = kk;
        if (!(x <= two_k)) {
            float t = std::clamp((x - two_k) / two_k, 0.0f, 1.0f);
            float w = k * (1.0f - t * t * (3.0f - 2.0f * t));
            ww = w * w;
        }
        d = 0.5f * (d + next - std::sqrt(x * x + ww));
    }
    return std::min(std::max(d, nearest - 0.5f * blend_), margin_);
}

void SphereField::evaluate(std::span<const glm::vec3> points, std::span<float> values) const {
    assert(points.size() == values.size());
    for (std::size_t i = 0; i < points.size(); ++i) values[i] = (*this)(points[i]);
}

}  // namespace sylva
