// How closely an octahedral impostor stands for its tree: the atlas drawn as the engines'
// shaders draw it (atlas_sampler.h) against the tree rendered by the baker's rasterizer
// from the same direction, at the tile's resolution, from every capture direction and
// from 8 directions between them. What the fidelity tests assert and sylva-bench-impostor
// prints (docs/impostors.md). Thread-safe; runs the directions on the TBB pool.
#pragma once

#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "impostor/impostor_bake.h"

namespace sylva {

// Silhouettes are alpha >= 0.5 (the shaders' alpha test).
struct ImpostorFidelity {
    double capture_iou = 1.0;     // the worst silhouette IoU over the capture directions
    double between_iou = 1.0;     // the worst over the directions between them
    double color = 0.0;           // the worst mean |difference| of sRGB bytes inside both
    std::vector<double> between;  // each in-between direction's IoU, in between_directions() order
};

// The 8 directions between the views of an N x N layout: centroids of grid half-cells
// (where the three views weigh alike), from the horizon to near the top, all around; the
// same cells of the layout's grid whatever N, so layouts compare at like places.
std::vector<glm::vec3> between_directions(int views = 8);

ImpostorFidelity impostor_fidelity(std::span<const BakePart> parts, const ImpostorAtlas& atlas);

}  // namespace sylva
