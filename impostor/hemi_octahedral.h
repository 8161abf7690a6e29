// The view layout of an octahedral impostor: N x N capture directions on the upper
// hemisphere, laid out on a square by the hemi-octahedral map (Brucks 2018; the octahedral
// map of Cigolle et al. 2014 folded to one hemisphere), and the three views a direction
// between them blends. The baker (impostor_bake.h), the CPU reference sampler
// (atlas_sampler.h) and every engine's shader (engine_kits/*/impostor_*) compute exactly
// these formulas, so a change here is a change of the file format (docs/impostors.md).
// Y is up. Pure functions, thread-safe.
#pragma once

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sylva {

// A unit direction with y >= 0 (y below 0 is clamped to the horizon) to the square
// [-1, 1]^2: p = (x, z) / (|x| + |y| + |z|), then (p.x + p.z, p.x - p.z).
glm::vec2 hemi_octahedral_encode(glm::vec3 direction);
// The inverse: a point of [-1, 1]^2 to the unit direction (y >= 0) it stands for.
glm::vec3 hemi_octahedral_decode(glm::vec2 square);

// View (i, j) of an N x N layout, i the column (left to right in the atlas image) and j
// the row (top down): the square point (i, j) / (N - 1) * 2 - 1, so the border views lie
// on the horizon and the corners look along +x, +z, -x, -z. Needs N >= 2.
glm::vec3 view_direction(int i, int j, int views);

// The camera of a view looking back along `direction` (toward the tree's centre):
// right = normalize(up_world x direction), up = direction x right; straight down
// (direction = +y) takes right = +x. An atlas tile shows right to the image's right and
// up to the image's top.
struct ViewFrame {
    glm::vec3 direction;  // from the centre toward the camera, unit
    glm::vec3 right;
    glm::vec3 up;
};
ViewFrame view_frame(glm::vec3 direction);

// The three views to blend for a camera looking from `direction`, and their weights (sum
// 1): the grid cell of the direction's square point is cut along its (1,0)-(0,1)
// diagonal and the barycentric weights of the half the point is in are used.
struct ViewBlend {
    std::array<glm::ivec2, 3> views;  // (i, j) as view_direction() takes them
    std::array<float, 3> weights;
};
ViewBlend view_blend(glm::vec3 direction, int views);

}  // namespace sylva
