// Nearest-triangle queries on a mesh: a bounding volume hierarchy (median splits, boxes)
// over its triangles. Used to measure how far a reduced mesh strays from a reference.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "core/mesh.h"

namespace sylva {

class TriangleBvh {
  public:
    struct Hit {
        float distance = 0.0f;       // to the closest point; infinity for an empty mesh
        glm::vec3 point{0.0f};       // the closest point on the mesh
        std::uint32_t triangle = 0;  // index into the mesh's triangles
    };

    // Copies the triangles; the mesh need not outlive the tree. O(n log n).
    explicit TriangleBvh(const Mesh& mesh);

    // Exact closest point over all triangles. Const, so safe from many threads at once.
    Hit closest(const glm::vec3& p) const;
    float distance(const glm::vec3& p) const { return closest(p).distance; }

    // The squared distance from `p` to the mesh when it exceeds `bound2` (a squared
    // distance), else any value at most `bound2`: the search stops at the first triangle
    // that close. A Hausdorff distance (the largest of many nearest distances) needs only
    // this, and most points have a triangle nearer than the largest so far.
    float distance_squared_beyond(const glm::vec3& p, float bound2) const;

    std::size_t size() const { return triangles_.size(); }

  private:
    struct Triangle {
        glm::vec3 a, b, c;
        std::uint32_t index;
    };
    struct Node {
        glm::vec3 lo, hi;
        std::uint32_t first;  // leaf: first triangle; inner: index of the right child
        std::uint32_t count;  // leaf: triangle count; inner: 0 (the left child follows)
    };
    std::uint32_t build(std::uint32_t begin, std::uint32_t end);
    // The closest triangle's squared distance, point and index, the search stopping at the
    // first leaf that brings it within `enough_d2` (negative: never).
    float search(const glm::vec3& p, float enough_d2, glm::vec3& point,
                 std::uint32_t& triangle) const;

    std::vector<Triangle> triangles_;
    std::vector<Node> nodes_;
};

}  // namespace sylva
