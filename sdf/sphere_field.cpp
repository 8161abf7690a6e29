#include "sdf/sphere_field.h"

#include <xmmintrin.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/geometric.hpp>
#include <span>
#include <utility>

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

namespace {

// A ball is four floats (centre, radius): one load each.
static_assert(sizeof(Ball) == 4 * sizeof(float) && offsetof(Ball, radius) == 3 * sizeof(float));

// Four spheres' distances from p (x, y, z as broadcast), as distance() computes each.
inline __m128 distances4(const Ball* const balls[4], __m128 px, __m128 py, __m128 pz) {
    __m128 x = _mm_loadu_ps(&balls[0]->center.x), y = _mm_loadu_ps(&balls[1]->center.x),
           z = _mm_loadu_ps(&balls[2]->center.x), r = _mm_loadu_ps(&balls[3]->center.x);
    _MM_TRANSPOSE4_PS(x, y, z, r);
    const __m128 dx = _mm_sub_ps(px, x), dy = _mm_sub_ps(py, y), dz = _mm_sub_ps(pz, z);
    const __m128 d2 =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
    return _mm_sub_ps(_mm_sqrt_ps(d2), r);
}

}  // namespace

float SphereField::operator()(const glm::vec3& p) const {
    auto near = bins_.candidates(p);
    if (near.empty()) return margin_ + bins_.empty_distance(p);
    if (kind_ == SphereBlend::PaskoSavchenko) {
        float d = margin_;
        for (std::uint32_t i : near) d = pasko_savchenko_union(d, distance(balls_[i], p), blend_);
        return std::min(d, margin_);
    }
    // Nearest sphere first (sphere_field.h): the distances four at a time, for the nearest,
    // then again (kept, unless the bin lists more than kStored) for those within 4 k of it.
    const __m128 px = _mm_set1_ps(p.x), py = _mm_set1_ps(p.y), pz = _mm_set1_ps(p.z);
    const std::size_t n = near.size();
    auto next4 = [&](std::size_t at) {  // the last four repeat the last sphere
        const Ball* four[4];
        for (std::size_t j = 0; j < 4; ++j) four[j] = &balls_[near[std::min(at + j, n - 1)]];
        return distances4(four, px, py, pz);
    };
    constexpr std::size_t kStored = 128;
    alignas(16) float stored[kStored];
    __m128 low = _mm_set1_ps(margin_);
    for (std::size_t at = 0; at < n; at += 4) {
        const __m128 next = next4(at);
        if (at + 4 <= kStored) _mm_store_ps(stored + at, next);
        low = _mm_min_ps(low, next);
    }
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, low);
    const float nearest = std::min(std::min(lanes[0], lanes[1]), std::min(lanes[2], lanes[3]));
    // Those within 4 k, in the bins' order; a crowd of spheres at one place spills over.
    constexpr std::size_t kFew = 64;
    float few[kFew];
    std::vector<float> many;
    std::size_t count = 0;
    const __m128 reach = _mm_set1_ps(nearest + 4.0f * blend_);
    for (std::size_t at = 0; at < n; at += 4) {
        const __m128 next = at + 4 <= kStored ? _mm_load_ps(stored + at) : next4(at);
        const int within = _mm_movemask_ps(_mm_cmple_ps(next, reach));
        if (within == 0) continue;
        _mm_store_ps(lanes, next);
        for (std::size_t j = 0; j < 4 && at + j < n; ++j) {
            if (!(within & (1 << j))) continue;
            if (count == kFew) many.assign(few, few + kFew);
            if (count < kFew)
                few[count] = lanes[j];
            else
                many.push_back(lanes[j]);
            ++count;
        }
    }
    // Nearest first, each the nearest of those left. The value only falls: it stops where
    // the nearest left would leave it as it is (so would the rest), or where it reaches
    // k/2 below the nearest sphere, which it is kept within (a dense crown's many blends
    // get there after a few).
    const std::span<float> left = count <= kFew ? std::span(few, count) : std::span(many);
    const float fade = 4.0f * blend_, lowest = nearest - 0.5f * blend_;
    float d = margin_;
    for (std::size_t n_left = left.size(); n_left > 0 && d > lowest;) {
        std::size_t first = 0;
        for (std::size_t i = 1; i < n_left; ++i)
            if (left[i] < left[first]) first = i;
        const float next = left[first];
        if (next - d >= fade) break;
        d = blend_ > 0.0f ? local_root_smooth_min(d, next, blend_) : std::min(d, next);
        left[first] = left[--n_left];
    }
    return std::min(std::max(d, lowest), margin_);
}

void SphereField::evaluate(std::span<const glm::vec3> points, std::span<float> values) const {
    assert(points.size() == values.size());
    for (std::size_t i = 0; i < points.size(); ++i) values[i] = (*this)(points[i]);
}

}  // namespace sylva
