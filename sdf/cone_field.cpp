#include "sdf/cone_field.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "sdf/point_hash.h"

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

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

namespace {

#if defined(__SSE2__)
// std::max, std::min and std::clamp lane by lane, with their results for NaNs and signed
// zeros too: std::max(a, b) is a < b ? b : a, which _mm_max_ps(b, a) is.
__m128 max4(__m128 a, __m128 b) {
    return _mm_max_ps(b, a);
}
__m128 min4(__m128 a, __m128 b) {
    return _mm_min_ps(b, a);
}
__m128 clamp4(__m128 v, __m128 lo, __m128 hi) {
    return min4(max4(v, lo), hi);
}
__m128 select4(__m128 mask, __m128 yes, __m128 no) {
    return _mm_or_ps(_mm_and_ps(mask, yes), _mm_andnot_ps(mask, no));
}

// Quad `q` (four floats) of four cones, transposed: lane j of out[k] is float k of cone j's
// quad.
template <class Packed>
void load_quad(const Packed* const (&cones)[4], int q, __m128 (&out)[4]) {
    for (int j = 0; j < 4; ++j)
        out[j] = _mm_load_ps(reinterpret_cast<const float*>(cones[j]) + 4 * q);
    _MM_TRANSPOSE4_PS(out[0], out[1], out[2], out[3]);
}

// distance(PreparedCone, p) of four cones at once: the same operations in the same order
// (SSE has no fused multiply-add), so each lane is the scalar result bit for bit.
// a = {a.x, a.y, a.z, ba.x}, b = {ba.y, ba.z, ra, rb}, c = {rba, baba, k, unused}.
__m128 distance4(const __m128 (&a)[4], const __m128 (&b)[4], const __m128 (&c)[4], __m128 px,
                 __m128 py, __m128 pz) {
    const __m128 bax = a[3], bay = b[0], baz = b[1], ra = b[2], rb = b[3];
    const __m128 rba = c[0], baba = c[1], k = c[2];
    const __m128 zero = _mm_setzero_ps(), half = _mm_set1_ps(0.5f), one = _mm_set1_ps(1.0f);
    const __m128 pax = px - a[0], pay = py - a[1], paz = pz - a[2];
    const __m128 papa = pax * pax + pay * pay + paz * paz;
    const __m128 paba = (pax * bax + pay * bay + paz * baz) / baba;
    const __m128 x = _mm_sqrt_ps(max4(papa - paba * paba * baba, zero));
    const __m128 cax = max4(zero, x - select4(_mm_cmplt_ps(paba, half), ra, rb));
    const __m128 cay = _mm_andnot_ps(_mm_set1_ps(-0.0f), paba - half) - half;
    const __m128 f = clamp4((rba * (x - ra) + paba * baba) / k, zero, one);
    const __m128 cbx = x - ra - f * rba;
    const __m128 cby = paba - f;
    const __m128 inside = _mm_and_ps(_mm_cmplt_ps(cbx, zero), _mm_cmplt_ps(cay, zero));
    const __m128 s = select4(inside, _mm_set1_ps(-1.0f), one);
    const __m128 cone =
        s * _mm_sqrt_ps(min4(cax * cax + cay * cay * baba, cbx * cbx + cby * cby * baba));
    const __m128 sphere = _mm_sqrt_ps(papa) - max4(ra, rb);
    return select4(_mm_cmple_ps(baba, zero), sphere, cone);
}

float smallest_lane(__m128 v) {
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, v);
    return std::min(std::min(lanes[0], lanes[1]), std::min(lanes[2], lanes[3]));
}
#endif

}  // namespace

ConeField::ConeField(std::vector<CappedCone> cones, float margin, float joint_blend,
                     CancelFlag cancel)
    : cones_(std::move(cones)), margin_(margin), joint_blend_(joint_blend) {
    static_assert(sizeof(Packed) == 64 && offsetof(Packed, cone) == 16);
    std::vector<Aabb> boxes;
    boxes.reserve(cones_.size());
    packed_.reserve(cones_.size());
    for (const CappedCone& c : cones_) {
        Packed& p = packed_.emplace_back();
        p.center = 0.5f * (c.a + c.b);
        p.radius = 0.5f * glm::length(c.b - c.a) + std::max(c.ra, c.rb);
        p.cone = prepare(c);
        float r = std::max(c.ra, c.rb) + margin_;
        boxes.push_back({glm::min(c.a, c.b) - glm::vec3(r), glm::max(c.a, c.b) + glm::vec3(r)});
    }
    // A bin lists a cone only if some point of the bin can be within the inflation of it.
    const float inflation = margin_ + joint_blend_;
    bins_ = BinGrid(
        boxes, kMinBinInMargins * margin_, 40,
        [&](size_t i, std::span<const glm::vec3> centres, float radius,
            std::span<std::uint8_t> keep) {
            const PreparedCone& cone = packed_[i].cone;
            std::size_t j = 0;
#if defined(__SSE2__)
            // Four bins at a time: the cone in every lane, a bin's centre in each.
            const __m128 a[4] = {_mm_set1_ps(cone.a.x), _mm_set1_ps(cone.a.y),
                                 _mm_set1_ps(cone.a.z), _mm_set1_ps(cone.ba.x)};
            const __m128 b[4] = {_mm_set1_ps(cone.ba.y), _mm_set1_ps(cone.ba.z),
                                 _mm_set1_ps(cone.ra), _mm_set1_ps(cone.rb)};
            const __m128 c[4] = {_mm_set1_ps(cone.rba), _mm_set1_ps(cone.baba), _mm_set1_ps(cone.k),
                                 _mm_setzero_ps()};
            const __m128 reach = _mm_set1_ps(inflation + radius);
            for (; j + 4 <= centres.size(); j += 4) {
                const glm::vec3* q = &centres[j];
                const __m128 x = _mm_setr_ps(q[0].x, q[1].x, q[2].x, q[3].x);
                const __m128 y = _mm_setr_ps(q[0].y, q[1].y, q[2].y, q[3].y);
                const __m128 z = _mm_setr_ps(q[0].z, q[1].z, q[2].z, q[3].z);
                const int near = _mm_movemask_ps(_mm_cmplt_ps(distance4(a, b, c, x, y, z), reach));
                for (int l = 0; l < 4; ++l) keep[j + l] = (near >> l) & 1;
            }
#endif
            for (; j < centres.size(); ++j)
                keep[j] = distance(cone, centres[j]) < inflation + radius;
        },
        cancel);
}

float ConeField::operator()(const glm::vec3& p) const {
    // A cone whose bounding sphere is at least d + joint_blend away leaves the result
    // unchanged (min, and the polynomial blend is exactly min beyond its radius), so it is
    // skipped without an exact evaluation; the value stays exact.
    auto near = bins_.candidates(p);
    if (near.empty()) return margin_ + bins_.empty_distance(p);
#if defined(__SSE2__)
    if (joint_blend_ == 0.0f) return hard_union(p, near);
#endif
    float d = margin_;
    for (std::uint32_t i : near) {
        const Packed& c = packed_[i];
        float reach = d + joint_blend_ + c.radius;
        glm::vec3 offset = p - c.center;
        if (reach > 0.0f && glm::dot(offset, offset) >= reach * reach) continue;
        float next = distance(c.cone, p);
        d = joint_blend_ > 0.0f ? polynomial_smooth_min(d, next, joint_blend_) : std::min(d, next);
    }
    return std::min(d, margin_);
}

#if defined(__SSE2__)
float ConeField::hard_union(const glm::vec3& p, std::span<const std::uint32_t> near) const {
    // The min is the same in any order, so four cones are measured at once (the last one
    // repeated to fill the lanes), each four skipped when all their bounding spheres are out
    // of reach of the smallest distance so far.
    const __m128 px = _mm_set1_ps(p.x), py = _mm_set1_ps(p.y), pz = _mm_set1_ps(p.z);
    __m128 d = _mm_set1_ps(margin_);
    __m128 smallest = d;
    const std::size_t n = near.size();
    for (std::size_t i = 0; i < n; i += 4) {
        const Packed* const four[4] = {&packed_[near[i]], &packed_[near[std::min(i + 1, n - 1)]],
                                       &packed_[near[std::min(i + 2, n - 1)]],
                                       &packed_[near[std::min(i + 3, n - 1)]]};
        __m128 bound[4];
        load_quad(four, 0, bound);
        const __m128 ox = px - bound[0], oy = py - bound[1], oz = pz - bound[2];
        const __m128 reach = smallest + bound[3];
        const __m128 wanted = _mm_or_ps(_mm_cmple_ps(reach, _mm_setzero_ps()),
                                        _mm_cmplt_ps(ox * ox + oy * oy + oz * oz, reach * reach));
        if (_mm_movemask_ps(wanted) == 0) continue;
        __m128 a[4], b[4], c[4];
        load_quad(four, 1, a);
        load_quad(four, 2, b);
        load_quad(four, 3, c);
        d = min4(d, distance4(a, b, c, px, py, pz));
        smallest = _mm_set1_ps(smallest_lane(d));
    }
    return std::min(smallest_lane(d), margin_);
}
#endif

void ConeField::evaluate(std::span<const glm::vec3> points, std::span<float> values) const {
    assert(points.size() == values.size());
    for (std::size_t i = 0; i < points.size(); ++i) values[i] = (*this)(points[i]);
}

}  // namespace sylva
