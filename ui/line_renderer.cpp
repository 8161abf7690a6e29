#include "ui/line_renderer.h"

#include <glm/gtc/type_ptr.hpp>

namespace sylva::studio {
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
void main() { gl_Position = u_view_projection * vec4(a_position, 1.0); }
)";

constexpr const char* kFragmentShader = R"(#version 330 core
uniform vec3 u_color;
out vec4 frag_color;
void main() { frag_color = vec4(u_color, 1.0); }
)";

}  // namespace

LineRenderer::LineRenderer() : program_("lines", kVertexShader, kFragmentShader) {}

void LineRenderer::upload(std::span<const glm::vec3> points) {
    lines_.upload(points);
}

void LineRenderer::draw(const glm::mat4& view, const glm::mat4& projection,
                        const glm::vec3& color) const {
    draw_as(GL_LINES, view, projection, color);
}

void LineRenderer::draw_points(const glm::mat4& view, const glm::mat4& projection,
                               const glm::vec3& color, float size) const {
    glPointSize(size);
    draw_as(GL_POINTS, view, projection, color);
    glPointSize(1.0f);
}

void LineRenderer::draw_as(GLenum mode, const glm::mat4& view, const glm::mat4& projection,
                           const glm::vec3& color) const {
    if (lines_.count() == 0) return;
    glDisable(GL_DEPTH_TEST);
    glUseProgram(program_.id());
    glm::mat4 view_projection = projection * view;
    glUniformMatrix4fv(program_.uniform("u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view_projection));
    glUniform3fv(program_.uniform("u_color"), 1, glm::value_ptr(color));
    lines_.draw(mode);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace sylva::studio
