// The turtle's output: a tree graph (Liebemann 2017, 2.4.1) of tapered segments plus leaf
// polygons and organs (fruit, cones: surfaces placed by the turtle).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
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

// A predefined surface placed by the turtle (ABOP's `~`): which one, where, turned how, how
// big. tree/organ_surfaces.h knows the surfaces and meshes them.
struct Organ {
    std::string surface;  // its name, as the grammar wrote it after '~' ("apple")
    glm::vec3 position{0.0f};
    glm::vec3 heading{0.0f, 1.0f, 0.0f};  // the turtle's frame there: H, L, U
    glm::vec3 left{-1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 0.0f, 1.0f};
    float size = 0.0f;   // meters; 0: the surface's own size
    float scale = 1.0f;  // times the size: below 1 on a young tree (core/tree_age.h)
    int color = 0;       // colour index, as segments carry it
};

struct Skeleton {
    std::vector<Segment> segments;
    std::vector<std::vector<glm::vec3>> polygons;  // from { . } (and f moves inside { })
    // Per polygon, its colour index (the turtle's at '{'); empty when no producer set it
    // (then every polygon has colour 0).
    std::vector<int> polygon_colors;
    std::vector<Organ> organs;  // from ~name
};

// A polygon's colour index: polygon_colors[i], or 0 when there is none.
inline int polygon_color(const Skeleton& skeleton, std::size_t i) {
    return i < skeleton.polygon_colors.size() ? skeleton.polygon_colors[i] : 0;
}

// Segments with no child segment, in increasing index order.
std::vector<int> tips(const Skeleton& skeleton);

}  // namespace sylva
