#include "sdf/bin_grid.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <limits>
#include <utility>

namespace sylva {

BinGrid::BinGrid(std::span<const Aabb> boxes, float min_bin_size, int bins_along_longest,
                 const Overlap& overlaps, CancelFlag cancel) {
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
        lo = glm::clamp(glm::ivec3(glm::floor((b.min - origin_) / bin_size_)), glm::ivec3(0),
                        dims_ - 1);
        hi = glm::clamp(glm::ivec3(glm::floor((b.max - origin_) / bin_size_)), glm::ivec3(0),
                        dims_ - 1);
    };
    auto index = [&](int x, int y, int z) {
        return static_cast<size_t>((z * dims_.y + y) * dims_.x + x);
    };
    const float bin_radius = 0.5f * std::sqrt(3.0f) * bin_size_;
    auto keep = [&](size_t i, int x, int y, int z) {
        if (!overlaps) return true;
        glm::vec3 centre = origin_ + (glm::vec3(x, y, z) + 0.5f) * bin_size_;
        return overlaps(i, centre, bin_radius);
    };
    // Each box's bins, tested once (the overlap test is a primitive's distance per bin; the
    // boxes are tested in parallel, in chunks kept in box order), then a counting sort into
    // a compact CSR layout with items in box order.
    constexpr std::size_t kChunk = 256;
    const std::size_t chunks = (boxes.size() + kChunk - 1) / kChunk;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> listed(chunks);  // bin, box
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        if (is_cancelled(cancel)) return;
        for (std::size_t i = c * kChunk; i < std::min(boxes.size(), (c + 1) * kChunk); ++i) {
            glm::ivec3 lo, hi;
            range(boxes[i], lo, hi);
            for (int z = lo.z; z <= hi.z; ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x)
                        if (keep(i, x, y, z))
                            listed[c].emplace_back(static_cast<std::uint32_t>(index(x, y, z)),
                                                   static_cast<std::uint32_t>(i));
        }
    });
    throw_if_cancelled(cancel);
    bin_start_.assign(static_cast<size_t>(dims_.x) * dims_.y * dims_.z + 1, 0);
    for (const auto& chunk : listed)
        for (const auto& [bin, box] : chunk) ++bin_start_[bin + 1];
    for (size_t b = 1; b < bin_start_.size(); ++b) bin_start_[b] += bin_start_[b - 1];
    bin_items_.resize(bin_start_.back());
    std::vector<std::uint32_t> fill(bin_start_.begin(), bin_start_.end() - 1);
    for (const auto& chunk : listed)
        for (const auto& [bin, box] : chunk) bin_items_[fill[bin]++] = box;

    // Breadth-first over the 26-neighbourhood from every occupied bin: Chebyshev distances.
    const size_t count = bin_start_.size() - 1;
    bins_to_nearest_.assign(count, std::numeric_limits<std::uint16_t>::max());
    std::vector<std::uint32_t> frontier, next;
    for (size_t b = 0; b < count; ++b)
        if (bin_start_[b + 1] > bin_start_[b]) {
            bins_to_nearest_[b] = 0;
            frontier.push_back(static_cast<std::uint32_t>(b));
        }
    for (std::uint16_t level = 1; !frontier.empty() && level < 0xffff; ++level) {
        next.clear();
        for (std::uint32_t b : frontier) {
            int x = static_cast<int>(b % dims_.x), y = static_cast<int>(b / dims_.x % dims_.y),
                z = static_cast<int>(b / (static_cast<size_t>(dims_.x) * dims_.y));
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        int nx = x + dx, ny = y + dy, nz = z + dz;
                        if (nx < 0 || ny < 0 || nz < 0 || nx >= dims_.x || ny >= dims_.y ||
                            nz >= dims_.z)
                            continue;
                        size_t n = index(nx, ny, nz);
                        if (bins_to_nearest_[n] <= level) continue;
                        bins_to_nearest_[n] = level;
                        next.push_back(static_cast<std::uint32_t>(n));
                    }
        }
        std::swap(frontier, next);
    }
}

float BinGrid::empty_distance(const glm::vec3& p) const {
    if (bin_start_.empty()) return std::numeric_limits<float>::max();
    glm::vec3 grid_max = origin_ + glm::vec3(dims_) * bin_size_;
    glm::vec3 outside = glm::max(glm::max(origin_ - p, p - grid_max), glm::vec3(0.0f));
    if (outside != glm::vec3(0.0f)) return glm::length(outside);  // every box is inside
    glm::ivec3 cell = glm::min(glm::ivec3(glm::floor((p - origin_) / bin_size_)), dims_ - 1);
    auto b = static_cast<size_t>((cell.z * dims_.y + cell.y) * dims_.x + cell.x);
    // A bin k steps away (Chebyshev) is separated from p's bin by k - 1 whole bins.
    int k = bins_to_nearest_[b];
    return k <= 1 ? 0.0f : static_cast<float>(k - 1) * bin_size_;
}

std::span<const std::uint32_t> BinGrid::candidates(const glm::vec3& p) const {
    if (bin_start_.empty()) return {};
    glm::vec3 cell = glm::floor((p - origin_) / bin_size_);
    if (glm::any(glm::lessThan(cell, glm::vec3(0.0f))) ||
        glm::any(glm::greaterThanEqual(cell, glm::vec3(dims_))))
        return {};
    auto b = static_cast<size_t>((static_cast<int>(cell.z) * dims_.y + static_cast<int>(cell.y)) *
                                     dims_.x +
                                 static_cast<int>(cell.x));
    return {bin_items_.data() + bin_start_[b], bin_start_[b + 1] - bin_start_[b]};
}

}  // namespace sylva
