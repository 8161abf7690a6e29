// A tree drawn into a small square texture off screen, framed from the front and a little
// above: the Variants strip's and the template picker's thumbnails. Needs the GL context;
// call outside ImGui's drawing of the frame (it binds its own framebuffer and viewport, and
// leaves the window's framebuffer bound).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"
#include "core/tree_template.h"
#include "ui/gl.h"
#include "ui/mesh_renderer.h"

namespace sylva::studio {

// The renderers a batch of thumbnails shares (one upload each per thumbnail).
struct ThumbnailRenderers {
    MeshRenderer trunk, crown, leaves;
};

// Draws the parts into a new `size` x `size` RGBA texture and returns it (the caller deletes
// it). With `pixels`, the image is also read back into it (RGBA, bottom row first).
GLuint render_tree_thumbnail(const Mesh& trunk, const Mesh& crown, const Mesh& leaves,
                             const PartColors& colors, int size, ThumbnailRenderers& renderers,
                             std::vector<std::uint8_t>* pixels = nullptr);

// A new texture holding `pixels` (RGBA, bottom row first, `size` squared).
GLuint upload_thumbnail_texture(const std::vector<std::uint8_t>& pixels, int size);

}  // namespace sylva::studio
