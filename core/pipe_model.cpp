#include "core/pipe_model.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace sylva {

void apply_pipe_model(Skeleton& skeleton, float tip_radius, float exponent) {
    const size_t n = skeleton.segments.size();
    std::vector<double> sum(n, 0.0);  // sum of the children's r^g
    std::vector<float> largest_child(n, 0.0f);
    std::vector<bool> has_child(n, false);
    // Children come after their parents, so one backward pass sees every child first.
    for (size_t i = n; i-- > 0;) {
        Segment& s = skeleton.segments[i];
        float r = has_child[i] ? static_cast<float>(std::pow(sum[i], 1.0 / exponent)) : tip_radius;
        s.ra = r;
        s.rb = has_child[i] ? largest_child[i] : tip_radius;
        if (s.parent >= 0) {
            auto p = static_cast<size_t>(s.parent);
            assert(p < i);
            sum[p] += std::pow(static_cast<double>(r), static_cast<double>(exponent));
            largest_child[p] = std::max(largest_child[p], r);
            has_child[p] = true;
        }
    }
}

}  // namespace sylva
