// A small software rasterizer for impostor captures: the tree's coloured triangles seen
// from one direction through an orthographic camera, with a depth buffer and s x s
// samples per pixel, resolved to coverage (alpha), colour, normal and depth. Ours rather
// than a GL context: the core links no GL, the bytes are the same on every machine, and a
// game tree of a few thousand triangles in 128-pixel tiles is small work
// (third_party_notes.md). Thread-safe: no shared state; callers run views in parallel.
#pragma once

#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "core/mesh.h"
#include "impostor/hemi_octahedral.h"

namespace sylva {

// One part of the tree to capture: its mesh, its colour (linear RGB), optionally a tint
// per vertex multiplying it (export/part_attributes.h), and whether both sides are seen
// (leaves: the normal is turned toward the camera).
struct BakePart {
    const Mesh* mesh = nullptr;
    glm::vec3 color{0.7f};
    const std::vector<glm::vec3>* tint = nullptr;  // per vertex of *mesh, or null
    bool two_sided = false;
};

// The sphere every view frames: the centre of the parts' bounding box and the largest
// distance from it to a vertex (0 for no vertex).
struct BakeBounds {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};
BakeBounds bake_bounds(std::span<const BakePart> parts);

// A captured view, `size` x `size` pixels, row 0 at the top (image order). Colour is
// linear RGB averaged over the covered samples (not premultiplied), the normal the unit
// average of the covered faces' normals (object space), depth the signed distance toward
// the camera from the plane through the centre, averaged likewise. Uncovered pixels hold
// alpha 0, colour 0, normal 0, depth 0.
struct ViewImage {
    int size = 0;
    std::vector<float> alpha;
    std::vector<glm::vec3> color;
    std::vector<glm::vec3> normal;
    std::vector<float> depth;
};

// Renders `parts` seen from frame.direction: pixel (x, y) covers the square of the
// view's plane at right * [-r, r] and up * [r, -r] around bounds.center, with
// `samples` x `samples` samples on a regular grid inside it (1 to 8). Faces are flat:
// one normal and one colour (the mean of its corners' tints) each; faces of closed parts
// turned away from the camera are skipped (hidden by the front), two-sided ones turned.
ViewImage render_view(std::span<const BakePart> parts, const ViewFrame& frame,
                      const BakeBounds& bounds, int size, int samples);
// The same into `image`, reusing its memory (and per-thread scratch buffers).
void render_view(std::span<const BakePart> parts, const ViewFrame& frame, const BakeBounds& bounds,
                 int size, int samples, ViewImage& image);

}  // namespace sylva
