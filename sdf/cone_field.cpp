#include "sdf/cone_field.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace sylva {
namespace {

struct Bounds {
    glm::vec3 min, max;
};

Bounds inflated_bounds(const CappedCone& c, float margin) {
    float r = std::max(c.ra, c.rb) + margin;
    return {glm::min(c.a, c.b) - glm::vec3(r), glm::max(c.a, c.b) + glm::vec3(r)};
}

}  // namespace

ConeField::ConeField(std::vector<CappedCone> cones, float margin)
    : cones_(std::move(cones)), margin_(margin) {
    if (cones_.empty()) return;
    Bounds all = inflated_bounds(cones_[0], margin_);
    for (const CappedCone& c : cones_) {
        Bounds b = inflated_bounds(c, margin_);
        all.min = glm::min(all.min, b.min);
        all.max = glm::max(all.max, b.max);
    }
    // About 64 bins along the longest side, but no smaller than the inflation itself:
    // smaller bins would repeat every cone in many bins without culling more.
    glm::vec3 extent = all.max - all.min;
    float longest = std::max({extent.x, extent.y, extent.z});
    bin_size_ = std::max(longest / 64.0f, margin_);
    origin_ = all.min;
    dims_ = glm::max(glm::ivec3(glm::ceil(extent / bin_size_)), glm::ivec3(1));

    auto bin_range = [&](const CappedCone& c, glm::ivec3& lo, glm::ivec3& hi) {
        Bounds b = inflated_bounds(c, margin_);
        lo = glm::clamp(glm::ivec3(glm::floor((b.min - origin_) / bin_size_)), glm::ivec3(0),
                        dims_ - 1);
        hi = glm::clamp(glm::ivec3(glm::floor((b.max - origin_) / bin_size_)), glm::ivec3(0),
                        dims_ - 1);
    };
    auto bin_index = [&](int x, int y, int z) {
        return static_cast<size_t>((z * dims_.y + y) * dims_.x + x);
    };
    // Two passes (count, then fill) give a compact CSR layout.
    bin_start_.assign(static_cast<size_t>(dims_.x) * dims_.y * dims_.z + 1, 0);
    for (const CappedCone& c : cones_) {
        glm::ivec3 lo, hi;
        bin_range(c, lo, hi);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) ++bin_start_[bin_index(x, y, z) + 1];
    }
    for (size_t b = 1; b < bin_start_.size(); ++b) bin_start_[b] += bin_start_[b - 1];
    bin_cones_.resize(bin_start_.back());
    std::vector<std::uint32_t> fill(bin_start_.begin(), bin_start_.end() - 1);
    for (size_t i = 0; i < cones_.size(); ++i) {
        glm::ivec3 lo, hi;
        bin_range(cones_[i], lo, hi);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    bin_cones_[fill[bin_index(x, y, z)]++] = static_cast<std::uint32_t>(i);
    }
}

float ConeField::operator()(const glm::vec3& p) const {
    if (cones_.empty()) return margin_;
    glm::vec3 cell = glm::floor((p - origin_) / bin_size_);
    if (glm::any(glm::lessThan(cell, glm::vec3(0.0f))) ||
        glm::any(glm::greaterThanEqual(cell, glm::vec3(dims_))))
        return margin_;  // outside every inflated box
    auto b = static_cast<size_t>((static_cast<int>(cell.z) * dims_.y + static_cast<int>(cell.y)) *
                                     dims_.x +
                                 static_cast<int>(cell.x));
    float d = margin_;
    for (std::uint32_t k = bin_start_[b]; k < bin_start_[b + 1]; ++k)
        d = std::min(d, distance(cones_[bin_cones_[k]], p));
    return d;
}

}  // namespace sylva
