#include "sdf/cone_field.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <unordered_map>

namespace sylva {

float polynomial_smooth_min(float a, float b, float k) {
    float h = std::max(k - std::abs(a - b), 0.0f) / k;
    return std::min(a, b) - h * h * k * 0.25f;
}

namespace {

struct CellKey {
    long long v[6];
    bool operator==(const CellKey& o) const {
        for (int i = 0; i < 6; ++i)
            if (v[i] != o.v[i]) return false;
        return true;
    }
};

struct CellKeyHash {
    std::size_t operator()(const CellKey& k) const {
        std::size_t h = 1469598103934665603ull;
        for (long long x : k.v) h = (h ^ static_cast<std::size_t>(x)) * 1099511628211ull;
        return h;
    }
};

}  // namespace

std::vector<CappedCone> merge_coincident_cones(std::vector<CappedCone> cones, float tolerance) {
    if (!(tolerance > 0.0f)) return cones;
    auto quantize = [tolerance](const glm::vec3& p, long long* out) {
        for (int i = 0; i < 3; ++i) out[i] = std::llround(double(p[i]) / tolerance);
    };
    std::unordered_map<CellKey, std::size_t, CellKeyHash> first;
    first.reserve(cones.size());
    std::vector<CappedCone> out;
    out.reserve(cones.size());
    for (const CappedCone& c : cones) {
        const glm::vec3 ends[2] = {c.a, c.b};
        bool finite = true;
        for (const glm::vec3& e : ends)
            for (int i = 0; i < 3; ++i)
                finite = finite && std::abs(double(e[i]) / tolerance) < 1e15;
        if (!finite) {
            out.push_back(c);
            continue;
        }
        CellKey key;
        quantize(c.a, key.v);
        quantize(c.b, key.v + 3);
        // One key for both directions of a segment: the smaller end first.
        if (std::lexicographical_compare(key.v + 3, key.v + 6, key.v, key.v + 3))
            std::swap_ranges(key.v, key.v + 3, key.v + 3);
        auto [it, inserted] = first.try_emplace(key, out.size());
        if (inserted) {
            out.push_back(c);
            continue;
        }
        CappedCone& kept = out[it->second];
        // `kept` may have been stored in either direction; match ends by position.
        const bool same_way = glm::distance(kept.a, c.a) <= glm::distance(kept.a, c.b);
        kept.ra = std::max(kept.ra, same_way ? c.ra : c.rb);
        kept.rb = std::max(kept.rb, same_way ? c.rb : c.ra);
    }
    return out;
}

ConeField::ConeField(std::vector<CappedCone> cones, float margin, float joint_blend)
    : cones_(std::move(cones)), margin_(margin), joint_blend_(joint_blend) {
    std::vector<Aabb> boxes;
    boxes.reserve(cones_.size());
    bounds_.reserve(cones_.size());
    for (const CappedCone& c : cones_) {
        bounds_.push_back(
            {0.5f * (c.a + c.b), 0.5f * glm::length(c.b - c.a) + std::max(c.ra, c.rb)});
        float r = std::max(c.ra, c.rb) + margin_;
        boxes.push_back({glm::min(c.a, c.b) - glm::vec3(r), glm::max(c.a, c.b) + glm::vec3(r)});
    }
    // A bin lists a cone only if some point of the bin can be within the inflation of it.
    const float inflation = margin_ + joint_blend_;
    bins_ =
        BinGrid(boxes, margin_ / 2.0f, 40, [&](size_t i, const glm::vec3& centre, float radius) {
            return distance(cones_[i], centre) < inflation + radius;
        });
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
        float next = distance(cones_[i], p);
        d = joint_blend_ > 0.0f ? polynomial_smooth_min(d, next, joint_blend_) : std::min(d, next);
    }
    return std::min(d, margin_);
}

void ConeField::evaluate(std::span<const glm::vec3> points, std::span<float> values) const {
    assert(points.size() == values.size());
    for (std::size_t i = 0; i < points.size(); ++i) values[i] = (*this)(points[i]);
}

}  // namespace sylva
