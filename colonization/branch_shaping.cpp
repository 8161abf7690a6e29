#include "colonization/branch_shaping.h"

#include <glm/geometric.hpp>
#include <vector>

#include "core/pipe_model.h"

namespace sylva {

void draw_successors_together(ColonizationGraph& graph, float amount) {
    if (amount <= 0.0f) return;
    std::vector<ColonizationNode>& nodes = graph.nodes;
    std::vector<std::vector<int>> children(nodes.size());
    for (size_t i = 1; i < nodes.size(); ++i)
        if (nodes[i].parent >= 0)
            children[static_cast<size_t>(nodes[i].parent)].push_back(static_cast<int>(i));
    for (size_t v = 0; v < nodes.size(); ++v) {
        if (children[v].size() < 2) continue;
        const glm::vec3 at = nodes[v].position;
        glm::vec3 mean(0.0f);
        for (int c : children[v])
            mean += glm::normalize(nodes[static_cast<size_t>(c)].position - at);
        if (glm::length(mean) < 1e-6f) continue;  // opposite successors: no common direction
        mean = glm::normalize(mean);
        for (int c : children[v]) {
            glm::vec3& p = nodes[static_cast<size_t>(c)].position;
            const float length = glm::length(p - at);
            const glm::vec3 turned = glm::normalize(p - at) * (1.0f - amount) + mean * amount;
            if (glm::length(turned) > 1e-6f) p = at + glm::normalize(turned) * length;
        }
    }
}

void reduce_curves(ColonizationGraph& graph, float max_dot) {
    if (max_dot >= 1.0f) return;
    std::vector<ColonizationNode>& nodes = graph.nodes;
    const size_t n = nodes.size();
    std::vector<int> only_child(n, -1);
    for (size_t i = 1; i < n; ++i)
        if (nodes[i].parent >= 0)
            only_child[static_cast<size_t>(nodes[i].parent)] = static_cast<int>(i);
    std::vector<char> removed(n, 0);
    std::vector<int> kept_parent(n, -1);  // nearest ancestor that stays
    for (size_t v = 0; v < n; ++v) {
        const int p = nodes[v].parent;
        if (p < 0) continue;
        kept_parent[v] = removed[static_cast<size_t>(p)] ? kept_parent[static_cast<size_t>(p)] : p;
        if (nodes[v].successors != 1) continue;
        const glm::vec3 r1 =
            glm::normalize(nodes[v].position - nodes[static_cast<size_t>(kept_parent[v])].position);
        const glm::vec3 r2 =
            glm::normalize(nodes[static_cast<size_t>(only_child[v])].position - nodes[v].position);
        if (glm::dot(r1, r2) > max_dot) removed[v] = 1;
    }
    std::vector<int> new_index(n, -1);
    std::vector<ColonizationNode> out;
    for (size_t v = 0; v < n; ++v) {
        if (removed[v]) continue;
        ColonizationNode node = nodes[v];
        node.parent = kept_parent[v] < 0 ? -1 : new_index[static_cast<size_t>(kept_parent[v])];
        node.successors = 0;
        new_index[v] = static_cast<int>(out.size());
        if (node.parent >= 0) ++out[static_cast<size_t>(node.parent)].successors;
        out.push_back(node);
    }
    nodes = std::move(out);
}

Skeleton to_skeleton(const ColonizationGraph& graph, float tip_radius, float exponent) {
    Skeleton skeleton;
    // segment_of[v]: the segment ending at node v (-1 for the root).
    std::vector<int> segment_of(graph.nodes.size(), -1);
    for (size_t v = 0; v < graph.nodes.size(); ++v) {
        const ColonizationNode& node = graph.nodes[v];
        if (node.parent < 0) continue;
        Segment s;
        s.a = graph.nodes[static_cast<size_t>(node.parent)].position;
        s.b = node.position;
        s.parent = segment_of[static_cast<size_t>(node.parent)];
        s.depth = node.depth;
        s.iteration = node.born;
        segment_of[v] = static_cast<int>(skeleton.segments.size());
        skeleton.segments.push_back(s);
    }
    apply_pipe_model(skeleton, tip_radius, exponent);
    return skeleton;
}

}  // namespace sylva
