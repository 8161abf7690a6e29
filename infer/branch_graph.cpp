#include "infer/branch_graph.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace sylva {
namespace {

glm::vec3 direction(const Segment& s) {
    return glm::normalize(s.b - s.a);
}

}  // namespace

BranchGraph build_branch_graph(const Skeleton& skeleton, std::span<const int> hint) {
    const std::vector<Segment>& segments = skeleton.segments;
    const std::size_t count = segments.size();
    BranchGraph g;
    g.children.resize(count);
    g.continuation.assign(count, -1);
    g.axis_of.assign(count, -1);
    g.height.assign(count, 1);
    for (std::size_t i = 0; i < count; ++i) {
        if (segments[i].parent < 0)
            g.roots.push_back(static_cast<int>(i));
        else
            g.children[static_cast<std::size_t>(segments[i].parent)].push_back(static_cast<int>(i));
    }
    const float kStraight = std::cos(glm::radians(45.0f));
    for (std::size_t i = 0; i < count; ++i) {
        const std::vector<int>& kids = g.children[i];
        if (kids.empty()) continue;
        if (i < hint.size() && hint[i] >= 0 &&
            std::find(kids.begin(), kids.end(), hint[i]) != kids.end()) {
            g.continuation[i] = hint[i];
            continue;
        }
        const glm::vec3 d = direction(segments[i]);
        const bool depths_known = segments[i].depth >= 0;
        int best = -1;
        float best_cos = -2.0f;
        for (int c : kids) {
            const Segment& child = segments[static_cast<std::size_t>(c)];
            if (depths_known && child.depth >= 0 && child.depth != segments[i].depth) continue;
            const float cosine = glm::dot(d, direction(child));
            if (cosine > best_cos) {
                best_cos = cosine;
                best = c;
            }
        }
        if (best >= 0 && (depths_known || best_cos >= kStraight)) g.continuation[i] = best;
    }
    for (std::size_t i = count; i-- > 0;) {
        int h = 0;
        for (int c : g.children[i]) h = std::max(h, g.height[static_cast<std::size_t>(c)]);
        g.height[i] = h + 1;
    }
    // Axes: each segment that is not a continuation starts one; parents come first, so
    // walking in index order creates a parent's axis before its laterals'.
    std::vector<char> continues(count, 0);
    for (int c : g.continuation)
        if (c >= 0) continues[static_cast<std::size_t>(c)] = 1;
    for (std::size_t i = 0; i < count; ++i) {
        if (continues[i]) continue;
        Axis axis;
        const Segment& first = segments[i];
        axis.parent_segment = first.parent;
        if (first.depth >= 0)
            axis.order = first.depth;
        else if (first.parent >= 0)
            axis.order =
                g.axes[static_cast<std::size_t>(g.axis_of[static_cast<std::size_t>(first.parent)])]
                    .order +
                1;
        const int id = static_cast<int>(g.axes.size());
        for (int s = static_cast<int>(i); s >= 0; s = g.continuation[static_cast<std::size_t>(s)]) {
            axis.segments.push_back(s);
            g.axis_of[static_cast<std::size_t>(s)] = id;
        }
        g.axes.push_back(std::move(axis));
    }
    return g;
}

}  // namespace sylva
