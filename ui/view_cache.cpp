#include "ui/view_cache.h"

namespace sylva::studio {

bool ViewCacheKey::operator==(const ViewCacheKey& o) const {
    const OrbitCamera &a = camera, &b = o.camera;
    return a.target == b.target && a.distance == b.distance && a.yaw_deg == b.yaw_deg &&
           a.pitch_deg == b.pitch_deg && a.fov_y_deg == b.fov_y_deg &&
           a.scene_radius == b.scene_radius && x == o.x && y == o.y && width == o.width &&
           height == o.height && scene == o.scene && toggles == o.toggles && trunk == o.trunk &&
           crown == o.crown && leaves == o.leaves;
}

ViewCache::ViewCache() {
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    available_ = samples == 0;
}

ViewCache::~ViewCache() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (color_) glDeleteTextures(1, &color_);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
}

void ViewCache::begin(const ViewCacheKey& key) {
    if (!framebuffer_ || width_ != key.width || height_ != key.height) {
        if (!framebuffer_) {
            glGenFramebuffers(1, &framebuffer_);
            glGenTextures(1, &color_);
            glGenRenderbuffers(1, &depth_);
        }
        glBindTexture(GL_TEXTURE_2D, color_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, key.width, key.height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindRenderbuffer(GL_RENDERBUFFER, depth_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, key.width, key.height);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
        width_ = key.width;
        height_ = key.height;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width_, height_);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    key_ = key;
    valid_ = true;
}

void ViewCache::copy() {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width_, height_, key_.x, key_.y, key_.x + width_, key_.y + height_,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace sylva::studio
