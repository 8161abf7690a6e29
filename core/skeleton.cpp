#include "core/skeleton.h"

namespace sylva {

std::vector<int> tips(const Skeleton& skeleton) {
    std::vector<bool> has_child(skeleton.segments.size(), false);
    for (const Segment& s : skeleton.segments)
        if (s.parent >= 0) has_child[static_cast<size_t>(s.parent)] = true;
    std::vector<int> out;
    for (size_t i = 0; i < has_child.size(); ++i)
        if (!has_child[i]) out.push_back(static_cast<int>(i));
    return out;
}

}  // namespace sylva
