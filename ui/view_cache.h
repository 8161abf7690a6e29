// The 3D view as last drawn, kept in a texture: while a text field has the keyboard and
// nothing in the view changed, a frame copies it instead of drawing the tree again. Under a
// software renderer (llvmpipe) drawing a full-detail tree is most of a frame, and the frame
// is what stands between a key and its character on screen.
//
// Needs the GL context; UI thread only. Off when the window's framebuffer is multisampled
// (a copy into it is not allowed; a GPU draws the tree fast anyway).
#pragma once

#include <glm/vec3.hpp>

#include "ui/gl.h"
#include "ui/state/orbit_camera.h"

namespace sylva::studio {

// What the view's pixels depend on when nothing moves: the camera, where the view is, the
// parts shown and their colours, and a serial that main raises with every upload.
struct ViewCacheKey {
    OrbitCamera camera;
    int x = 0, y = 0, width = 0, height = 0;
    long scene = 0;
    unsigned toggles = 0;  // the view toggles' bits and the LOD level
    glm::vec3 trunk{0.0f}, crown{0.0f}, leaves{0.0f};
    bool operator==(const ViewCacheKey& other) const;
};

class ViewCache {
  public:
    ViewCache();  // reads whether the window's framebuffer is multisampled
    ~ViewCache();
    ViewCache(const ViewCache&) = delete;
    ViewCache& operator=(const ViewCache&) = delete;

    bool available() const { return available_; }
    // True when the cached image was drawn for `key`: copy() it instead of drawing.
    bool holds(const ViewCacheKey& key) const { return valid_ && key == key_; }
    // Binds the cache's framebuffer (key.width x key.height), cleared, with its viewport:
    // draw the view into it, then copy().
    void begin(const ViewCacheKey& key);
    // Copies the cached image into the window's framebuffer at the key's place (and binds
    // the window's framebuffer again).
    void copy();
    // Forgets the image (a frame drew the view directly).
    void invalidate() { valid_ = false; }
    // The last frame copied the image without drawing the view.
    bool copied_last = false;

  private:
    bool available_ = false, valid_ = false;
    ViewCacheKey key_;
    GLuint framebuffer_ = 0, color_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0;  // of the attachments
};

}  // namespace sylva::studio
