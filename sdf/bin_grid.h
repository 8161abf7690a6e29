// A uniform grid of bins over a set of axis-aligned boxes: each bin lists the boxes that
// overlap it, so a query point only visits the primitives whose (inflated) box holds it.
// The culling structure behind the fast fields (cone_field.h, sphere_field.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "core/cancel.h"

namespace sylva {

struct Aabb {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

// The smallest bin of a field's grid, in multiples of its margin (the distance within which
// it is exact, which inflates every primitive's box). Smaller bins list each primitive in
// more bins (its box spans 2 (radius + margin)) without culling much more, so on the coarse
// grids of low budgets (wide cells, so a wide margin) building the field would cost more
// than the culling saves.
inline constexpr float kMinBinInMargins = 0.9f;

class BinGrid {
  public:
    BinGrid() = default;
    // About `bins_along_longest` bins along the longest side of all boxes together, but no
    // bin smaller than `min_bin_size` (smaller bins would repeat boxes without culling more).
    // `overlaps(i, centres, radius, keep)`, when given, refines box i's bins: it is called
    // once per box with the centres of all the bins of its box, and a bin stays listed only
    // if it sets keep[j] (which comes in as 1) for the ball (centres[j], radius) around bin j;
    // so long diagonal primitives are not listed in every bin of their bounding box, and a
    // field may test a primitive against several bins at once.
    // `overlaps` is called from several threads at once (boxes are binned in parallel); the
    // result does not depend on the thread count. Throws Cancelled once `cancel` is set
    // (polled per 256 boxes: a grid over tens of thousands of cones takes a noticeable time
    // to build).
    using Overlap = std::function<void(std::size_t, std::span<const glm::vec3>, float,
                                       std::span<std::uint8_t>)>;
    BinGrid(std::span<const Aabb> boxes, float min_bin_size, int bins_along_longest = 64,
            const Overlap& overlaps = {}, CancelFlag cancel = nullptr);

    // Indices of the boxes whose bin holds p (a superset of the boxes containing p), in
    // increasing order; empty outside every box.
    std::span<const std::uint32_t> candidates(const glm::vec3& p) const;

    // A lower bound on the distance from p to every box: 0 in a bin that lists boxes, else
    // how far the nearest such bin is at least (from a distance transform over the bins).
    float empty_distance(const glm::vec3& p) const;

  private:
    glm::vec3 origin_{0.0f};
    float bin_size_ = 1.0f;
    glm::ivec3 dims_{0};
    std::vector<std::uint32_t> bin_start_;  // CSR: boxes of bin b are
    std::vector<std::uint32_t> bin_items_;  // bin_items_[bin_start_[b] .. bin_start_[b+1])
    // Chebyshev distance, in bins, from each bin to the nearest bin that lists boxes.
    std::vector<std::uint16_t> bins_to_nearest_;
};

}  // namespace sylva
