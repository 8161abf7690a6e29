#include "sdf/bin_grid.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <limits>
#include <utility>

namespace sylva {

namespace {

// Chebyshev (chessboard) distances, in bins, from each bin to the nearest bin that lists
// boxes (bin b lists boxes when start[b + 1] > start[b]), 0xffff where there is none or it is
// farther: the shortest paths over the 26-neighbourhood. Two raster passes of the chamfer
// mask with unit weights give them exactly (Rosenfeld and Pfaltz for the plane, Borgefors in
// any dimension): forward with the 13 neighbours before a bin, backward with the 13 after. A
// border of 0xffff around the grid spares the bounds tests.
std::vector<std::uint16_t> chessboard_distances(const glm::ivec3& dims,
                                                const std::vector<std::uint32_t>& start) {
    constexpr std::uint16_t kFar = std::numeric_limits<std::uint16_t>::max();
    const std::ptrdiff_t px = dims.x + 2, py = dims.y + 2, pz = dims.z + 2;
    std::vector<std::uint16_t> padded(static_cast<std::size_t>(px * py * pz), kFar);
    auto at = [&](int x, int y, int z) { return ((z + 1) * py + (y + 1)) * px + (x + 1); };
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x) {
                const std::size_t b = (static_cast<std::size_t>(z) * dims.y + y) * dims.x + x;
                if (start[b + 1] > start[b]) padded[static_cast<std::size_t>(at(x, y, z))] = 0;
            }
    // Offsets of the 13 neighbours that come before a bin in raster order; the backward pass
    // uses their negatives.
    std::ptrdiff_t before[13];
    int n = 0;
    for (int dz = -1; dz <= 0; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const std::ptrdiff_t o = (dz * py + dy) * px + dx;
                if (o < 0) before[n++] = o;
            }
    std::uint16_t* v = padded.data();
    auto relax = [&](std::ptrdiff_t i, std::ptrdiff_t sign) {
        int m = v[i];  // a neighbour at kFar offers kFar + 1, never taken
        for (std::ptrdiff_t o : before) m = std::min(m, v[i + sign * o] + 1);
        v[i] = static_cast<std::uint16_t>(m);
    };
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x) relax(at(x, y, z), 1);
    for (int z = dims.z - 1; z >= 0; --z)
        for (int y = dims.y - 1; y >= 0; --y)
            for (int x = dims.x - 1; x >= 0; --x) relax(at(x, y, z), -1);
    std::vector<std::uint16_t> out(static_cast<std::size_t>(dims.x) * dims.y * dims.z);
    std::size_t b = 0;
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x) out[b++] = v[at(x, y, z)];
    return out;
}

}  // namespace

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
    // Each box's bins, tested once (the overlap test is a primitive's distance per bin; the
    // boxes are tested in parallel, in chunks kept in box order), then a counting sort into
    // a compact CSR layout with items in box order. Small chunks: a crown sphere covers
    // hundreds of bins, so an oak's 128 spheres are a few milliseconds of tests.
    constexpr std::size_t kChunk = 8;
    const std::size_t chunks = (boxes.size() + kChunk - 1) / kChunk;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> listed(chunks);  // bin, box
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
        if (is_cancelled(cancel)) return;
        std::vector<glm::vec3> centres;
        std::vector<std::uint32_t> bins;
        std::vector<std::uint8_t> keep;
        for (std::size_t i = c * kChunk; i < std::min(boxes.size(), (c + 1) * kChunk); ++i) {
            glm::ivec3 lo, hi;
            range(boxes[i], lo, hi);
            centres.clear();
            bins.clear();
            for (int z = lo.z; z <= hi.z; ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x) {
                        centres.push_back(origin_ + (glm::vec3(x, y, z) + 0.5f) * bin_size_);
                        bins.push_back(static_cast<std::uint32_t>(index(x, y, z)));
                    }
            keep.assign(bins.size(), 1);
            if (overlaps) overlaps(i, centres, bin_radius, keep);
            for (std::size_t j = 0; j < bins.size(); ++j)
                if (keep[j]) listed[c].emplace_back(bins[j], static_cast<std::uint32_t>(i));
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

    bins_to_nearest_ = chessboard_distances(dims_, bin_start_);
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
