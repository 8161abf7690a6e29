#include "ui/impostor_view.h"

#include <chrono>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <string>
#include <vector>

#include "impostor/impostor_mesh.h"

namespace sylva::studio {

extern const char* const kImpostorGlsl;  // docs/impostor.glsl (impostor_glsl.cpp.in)

namespace {

std::string stage(const char* define) {
    return std::string("#version 330 core\n#define ") + define + "\n" + kImpostorGlsl;
}

GLuint texture(const Image8& image, bool srgb) {
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const GLenum format = image.channels == 4 ? GL_RGBA : GL_RGB;
    const GLint internal = srgb ? (image.channels == 4 ? GL_SRGB8_ALPHA8 : GL_SRGB8)
                                : (image.channels == 4 ? GL_RGBA8 : GL_RGB8);
    glTexImage2D(GL_TEXTURE_2D, 0, internal, image.width, image.height, 0, format, GL_UNSIGNED_BYTE,
                 image.pixels.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return id;
}

}  // namespace

ImpostorView::ImpostorView()
    : program_("impostor", stage("SYLVA_IMPOSTOR_VERTEX").c_str(),
               stage("SYLVA_IMPOSTOR_FRAGMENT").c_str()) {
    glGenVertexArrays(1, &vertex_array_);
    glGenBuffers(1, &vertex_buffer_);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindVertexArray(0);
}

ImpostorView::~ImpostorView() {
    if (job_.valid()) job_.wait();  // the worker reads the tree it holds
    glDeleteTextures(1, &albedo_);
    glDeleteTextures(1, &normal_);
    glDeleteBuffers(1, &vertex_buffer_);
    glDeleteVertexArrays(1, &vertex_array_);
}

void ImpostorView::update(const std::shared_ptr<const GeneratedTree>& tree,
                          const PartColors& colors) {
    if (tree && tree != baking_ && tree != baked_ && !job_.valid()) {
        baking_ = tree;
        job_ = std::async(std::launch::async, [tree, colors] {
            const ShownParts level0 = shown_parts(*tree, 0);
            const BakePart parts[] = {{&level0.trunk, colors.trunk, nullptr, false},
                                      {&level0.crown, colors.crown, nullptr, false},
                                      {&level0.leaves, colors.leaves, nullptr, true}};
            return bake_impostor(parts, ImpostorSettings{});
        });
    }
    if (!job_.valid() || job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return;
    ImpostorAtlas atlas = job_.get();
    baked_ = baking_;
    glDeleteTextures(1, &albedo_);
    glDeleteTextures(1, &normal_);
    albedo_ = texture(atlas.albedo, true);
    normal_ = texture(atlas.normal, false);
    const TexturedMesh quad = impostor_quad(atlas);  // the exported quad, as engines get it
    std::vector<glm::vec3> corners;
    for (const auto& t : quad.mesh.triangles)
        for (std::uint32_t v : t) corners.push_back(quad.mesh.positions[v]);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners.size() * sizeof(glm::vec3)),
                 corners.data(), GL_STATIC_DRAW);
    atlas.albedo.pixels = {};
    atlas.normal.pixels = {};
    atlas_ = std::move(atlas);
    ready_ = true;
}

void ImpostorView::draw(const glm::mat4& view, const glm::mat4& projection,
                        const glm::vec3& eye) const {
    if (!ready_) return;
    glUseProgram(program_.id());
    const glm::mat4 mvp = projection * view;
    glUniformMatrix4fv(program_.uniform("model_view_projection"), 1, GL_FALSE, glm::value_ptr(mvp));
    glUniform1f(program_.uniform("impostor_views"), static_cast<float>(atlas_.views));
    glUniform3fv(program_.uniform("impostor_center"), 1, glm::value_ptr(atlas_.bounds.center));
    glUniform1f(program_.uniform("impostor_radius"), atlas_.bounds.radius);
    glUniform3fv(program_.uniform("camera_position"), 1, glm::value_ptr(eye));
    // The studio's key light comes from the upper left of the camera; here from above front.
    const glm::vec3 light = glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f));
    glUniform3fv(program_.uniform("light_direction"), 1, glm::value_ptr(light));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, albedo_);
    glUniform1i(program_.uniform("impostor_albedo"), 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, normal_);
    glUniform1i(program_.uniform("impostor_normal"), 1);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(vertex_array_);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace sylva::studio
