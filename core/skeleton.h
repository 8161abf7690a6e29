// The turtle's output: a tree graph (Liebemann 2017, 2.4.1) of tapered segments plus leaf polygons.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace sylva {

struct Segment {
    glm::vec3 a{0.0f};  // start point
    glm::vec3 b{0.0f};  // end point
    float ra = 0.0f;    // radius at a
    float rb = 0.0f;    // radius at b
    int parent = -1;    // index of the segment this one grows from, -1 for a root
    int depth = 0;      // branch depth Z: 0 on the trunk, +1 for every branch entered
    int color = 0;      // colour index set by '
    // The growth step that made it (colonization: the node's `born`, 0 for the trunk), so
    // growth can be replayed step by step; 0 for the L-system. Not exported.
    int iteration = 0;
};

struct Skeleton {
    std::vector<Segment> segments;
    std::vector<std::vector<glm::vec3>> polygons;  // from { . }
};

// Segments with no child segment, in increasing index order.
std::vector<int> tips(const Skeleton& skeleton);

}  // namespace sylva
