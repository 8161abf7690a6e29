#include "sdf/bin_grid.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>

namespace sylva {

BinGrid::BinGrid(std::span<const Aabb> boxes, float min_bin_size, int bins_along_longest) {
    if (boxes.empty()) return;
    Aabb all = boxes[0];
    for (const Aabb& b : boxes) {
        all.min = glm::min(all.min, b.min);
        all.max = glm::max(all.max, b.max);
    }
    glm::vec3 extent = all.max - all.min;
    float longest = std::max({extent.x, extent.y, extent.z});
    bin_size_ = std::max(longest / static_cast<float>(bins_along_longest), min_bin_size);
    if (!(bin_size_ > 0.0f)) bin_size_ = 1.0f;
    origin_ = all.min;
    dims_ = glm::max(glm::ivec3(glm::ceil(extent / bin_size_)), glm::ivec3(1));

    auto range = [&](const Aabb& b, glm::ivec3& lo, glm::ivec3& hi) {
        lo = glm::clamp(glm::ivec3(glm::floor((b.min - origin_) / bin_size_)), glm::ivec3(0), dims_ - 1);
        hi = glm::clamp(glm::ivec3(glm::floor((b.max - origin_) / bin_size_)), glm::ivec3(0), dims_ - 1);
    };
    auto index = [&](int x, int y, int z) {
        return static_cast<size_t>((z * dims_.y + y) * dims_.x + x);
    };
    // Two passes (count, then fill) give a compact CSR layout with items in box order.
    bin_start_.assign(static_cast<size_t>(dims_.x) * dims_.y * dims_.z + 1, 0);
    for (const Aabb& b : boxes) {
        glm::ivec3 lo, hi;
        range(b, lo, hi);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) ++bin_start_[index(x, y, z) + 1];
    }
    for (size_t b = 1; b < bin_start_.size(); ++b) bin_start_[b] += bin_start_[b - 1];
    bin_items_.resize(bin_start_.back());
    std::vector<std::uint32_t> fill(bin_start_.begin(), bin_start_.end() - 1);
    for (size_t i = 0; i < boxes.size(); ++i) {
        glm::ivec3 lo, hi;
        range(boxes[i], lo, hi);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    bin_items_[fill[index(x, y, z)]++] = static_cast<std::uint32_t>(i);
    }
}

std::span<const std::uint32_t> BinGrid::candidates(const glm::vec3& p) const {
    if (bin_start_.empty()) return {};
    glm::vec3 cell = glm::floor((p - origin_) / bin_size_);
    if (glm::any(glm::lessThan(cell, glm::vec3(0.0f))) ||
        glm::any(glm::greaterThanEqual(cell, glm::vec3(dims_))))
        return {};
    auto b = static_cast<size_t>(
        (static_cast<int>(cell.z) * dims_.y + static_cast<int>(cell.y)) * dims_.x +
        static_cast<int>(cell.x));
    return {bin_items_.data() + bin_start_[b], bin_start_[b + 1] - bin_start_[b]};
}

}  // namespace sylva
