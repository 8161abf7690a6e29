// How alike two trees look from afar: the overlap of their silhouettes seen from the
// sides and from above. A game mesh is seen at a distance first, where its outline is
// what a player reads; the silhouette against the full-detail tree says what a reduction
// kept of it, leaves included, however different the triangles are.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "core/mesh.h"

namespace sylva {

// Eight views around Y (Y is up) at azimuths 0, 45, ..., 315 degrees, each looking
// 15 degrees down, then one straight down from above. Orthographic.
inline constexpr int kSilhouetteViews = 9;

// Where the views look: a sphere around the reference, the same for every view and for
// every set of meshes compared with it.
struct SilhouetteFrame {
    glm::dvec3 center{0.0};
    double radius = 0.0;  // each image spans 2 radius on both axes
};

// The centre of the meshes' bounding box and the largest distance of a vertex from it,
// times 1.25, so a candidate that strays a quarter of that beyond the reference is still
// seen.
// Throws InputError (core/errors.h) when the meshes have no triangles. Meshes are not null.
SilhouetteFrame silhouette_frame(std::span<const Mesh* const> meshes);

// One byte per pixel and view, row by row from the bottom: 1 where a triangle covers the pixel's
// centre (either side of the triangle; the edges count as covered).
struct Silhouettes {
    int resolution = 0;
    std::array<std::vector<std::uint8_t>, kSilhouetteViews> views;
};

// All triangles of all meshes (trunk, crown and leaves alike) drawn in the frame's views at
// `resolution` x `resolution` pixels; what lies beyond the frame is not seen. Needs a
// resolution of at least 1 and a frame of positive radius. Deterministic; safe to call from
// several threads at once. Costs O(triangles x views + pixels covered).
Silhouettes rasterize_silhouettes(std::span<const Mesh* const> meshes, const SilhouetteFrame& frame,
                                  int resolution = 256);

struct SilhouetteScore {
    // Intersection over union of the covered pixels, per view in kSilhouetteViews' order:
    // 1 when both cover the same pixels (or none), 0 when they share none.
    std::array<double, kSilhouetteViews> views{};
    double mean = 0.0;  // over the views
};

// Silhouettes of one resolution, made in one frame.
SilhouetteScore silhouette_iou(const Silhouettes& reference, const Silhouettes& candidate);

// The candidate's silhouettes against the reference's, both in the reference's frame
// (silhouette_frame(reference)). Throws InputError when the reference has no triangles.
SilhouetteScore silhouette_iou(std::span<const Mesh* const> reference,
                               std::span<const Mesh* const> candidate, int resolution = 256);

}  // namespace sylva
