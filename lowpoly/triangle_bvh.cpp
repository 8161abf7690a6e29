#include "lowpoly/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

namespace sylva {
namespace {

constexpr std::uint32_t kLeafSize = 4;

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::vec3 closest_on_triangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                              const glm::vec3& c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return a;
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return b;
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return c;
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const float sum = va + vb + vc;
    if (!(sum > 0.0f)) return a;  // degenerate triangle
    const float v = vb / sum, w = vc / sum;
    return a + ab * v + ac * w;
}

float box_distance_squared(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 d = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
    return glm::dot(d, d);
}

}  // namespace

TriangleBvh::TriangleBvh(const Mesh& mesh) {
    triangles_.reserve(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        triangles_.push_back({mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]],
                              static_cast<std::uint32_t>(i)});
    }
    if (!triangles_.empty()) {
        nodes_.reserve(2 * triangles_.size() / kLeafSize + 1);
        build(0, static_cast<std::uint32_t>(triangles_.size()));
    }
}

std::uint32_t TriangleBvh::build(std::uint32_t begin, std::uint32_t end) {
    const auto node = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    glm::vec3 clo = lo, chi = hi;  // bounds of the centroids
    for (std::uint32_t i = begin; i < end; ++i) {
        const Triangle& t = triangles_[i];
        lo = glm::min(lo, glm::min(t.a, glm::min(t.b, t.c)));
        hi = glm::max(hi, glm::max(t.a, glm::max(t.b, t.c)));
        const glm::vec3 centroid = (t.a + t.b + t.c) / 3.0f;
        clo = glm::min(clo, centroid);
        chi = glm::max(chi, centroid);
    }
    nodes_[node].lo = lo;
    nodes_[node].hi = hi;
    if (end - begin <= kLeafSize) {
        nodes_[node].first = begin;
        nodes_[node].count = end - begin;
        return node;
    }
    const glm::vec3 extent = chi - clo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(triangles_.begin() + begin, triangles_.begin() + mid, triangles_.begin() + end,
                     [axis](const Triangle& x, const Triangle& y) {
                         return x.a[axis] + x.b[axis] + x.c[axis] <
                                y.a[axis] + y.b[axis] + y.c[axis];
                     });
    build(begin, mid);
    const std::uint32_t right = build(mid, end);
    nodes_[node].first = right;
    nodes_[node].count = 0;
    return node;
}

TriangleBvh::Hit TriangleBvh::closest(const glm::vec3& p) const {
    Hit best;
    const float d2 = search(p, -1.0f, best.point, best.triangle);
    best.distance = std::sqrt(d2);
    return best;
}

float TriangleBvh::distance_squared_beyond(const glm::vec3& p, float bound2) const {
    glm::vec3 point;
    std::uint32_t triangle = 0;
    return search(p, bound2, point, triangle);
}

float TriangleBvh::search(const glm::vec3& p, float enough_d2, glm::vec3& point,
                          std::uint32_t& triangle) const {
    float best_d2 = std::numeric_limits<float>::infinity();
    if (nodes_.empty()) return best_d2;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        if (box_distance_squared(p, n.lo, n.hi) >= best_d2) continue;
        if (n.count > 0) {
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                const Triangle& t = triangles_[i];
                const glm::vec3 q = closest_on_triangle(p, t.a, t.b, t.c);
                const float d2 = glm::dot(q - p, q - p);
                if (d2 < best_d2) {
                    best_d2 = d2;
                    point = q;
                    triangle = t.index;
                }
            }
            if (best_d2 <= enough_d2) return best_d2;
            continue;
        }
        // Visit the nearer child first: its hits prune the other.
        const std::uint32_t left = static_cast<std::uint32_t>(&n - nodes_.data()) + 1;
        const std::uint32_t right = n.first;
        const float dl = box_distance_squared(p, nodes_[left].lo, nodes_[left].hi);
        const float dr = box_distance_squared(p, nodes_[right].lo, nodes_[right].hi);
        if (dl < dr) {
            if (dr < best_d2) stack[top++] = right;
            if (dl < best_d2) stack[top++] = left;
        } else {
            if (dl < best_d2) stack[top++] = left;
            if (dr < best_d2) stack[top++] = right;
        }
    }
    return best_d2;
}

}  // namespace sylva
