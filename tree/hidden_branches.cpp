#include "tree/hidden_branches.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "tree/field_grid.h"

namespace sylva {

std::vector<std::uint8_t> visible_segments(const Skeleton& skeleton, const SphereField& crown,
                                           float cell) {
    // Each segment on its own, in parallel: a conifer has thousands.
    std::vector<std::uint8_t> shown(skeleton.segments.size());
    tbb::parallel_for(std::size_t{0}, skeleton.segments.size(), [&](std::size_t i) {
        const Segment& s = skeleton.segments[i];
        const float r = std::max({s.ra, s.rb, kMinRadiusInCells * cell});
        const float depth = std::max(s.ra, s.rb) < 0.5f * cell ? 0.0f : r;
        const int samples = 2 + static_cast<int>(glm::distance(s.a, s.b) / (0.5f * r));
        bool hidden = true;
        for (int k = 0; k <= samples && hidden; ++k)
            hidden = crown(glm::mix(s.a, s.b, static_cast<float>(k) / samples)) < -depth;
        shown[i] = !hidden;
    });
    return shown;
}

}  // namespace sylva
