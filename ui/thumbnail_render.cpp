#include "ui/thumbnail_render.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

namespace sylva::studio {
namespace {

GLuint new_texture(int size, const void* pixels) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return texture;
}

}  // namespace

GLuint render_tree_thumbnail(const Mesh& trunk, const Mesh& crown, const Mesh& leaves,
                             const PartColors& colors, int size, ThumbnailRenderers& renderers,
                             std::vector<std::uint8_t>* pixels) {
    const GLuint texture = new_texture(size, nullptr);
    GLuint depth = 0, framebuffer = 0;
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);

    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Mesh* m : {&trunk, &crown, &leaves})
        for (const glm::vec3& p : m->positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    if (lo.x > hi.x) lo = hi = glm::vec3(0.0f);
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 0.1f);
    const float distance = radius / std::sin(glm::radians(17.0f));
    const glm::vec3 eye = centre + distance * glm::normalize(glm::vec3(0.35f, 0.25f, 1.0f));
    const glm::mat4 view = glm::lookAt(eye, centre, glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 projection =
        glm::perspective(glm::radians(36.0f), 1.0f, 0.05f * distance, 4.0f * distance);

    glViewport(0, 0, size, size);
    glClearColor(0.20f, 0.22f, 0.25f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    renderers.trunk.upload(trunk);
    renderers.crown.upload(crown);
    renderers.leaves.upload(leaves);
    renderers.trunk.draw(view, projection, colors.trunk);
    renderers.crown.draw(view, projection, colors.crown);
    renderers.leaves.draw(view, projection, colors.leaves);
    if (pixels) {
        pixels->resize(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, pixels->data());
    }

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &depth);
    return texture;
}

GLuint upload_thumbnail_texture(const std::vector<std::uint8_t>& pixels, int size) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    return new_texture(size, pixels.data());
}

}  // namespace sylva::studio
