#include "ui/backdrop.h"

namespace sylva::studio {
namespace {

// One triangle covering the screen, positions from gl_VertexID: no vertex buffer.
constexpr const char* kVertexShader = R"(#version 330 core
out float v_height;
void main() {
    vec2 corner = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    v_height = 0.5 * corner.y + 0.5;
    gl_Position = vec4(corner, 0.0, 1.0);
}
)";

// Colours are gamma-encoded already; the gradient is subtle enough that it needs no dither.
constexpr const char* kFragmentShader = R"(#version 330 core
in float v_height;
out vec4 frag_color;
void main() {
    vec3 bottom = vec3(0.075, 0.082, 0.098);
    vec3 top = vec3(0.20, 0.225, 0.27);
    frag_color = vec4(mix(bottom, top, smoothstep(0.0, 1.0, v_height)), 1.0);
}
)";

}  // namespace

Backdrop::Backdrop() : program_("backdrop", kVertexShader, kFragmentShader) {
    glGenVertexArrays(1, &vertex_array_);
}

Backdrop::~Backdrop() {
    glDeleteVertexArrays(1, &vertex_array_);
}

void Backdrop::draw() const {
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glUseProgram(program_.id());
    glBindVertexArray(vertex_array_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
}

}  // namespace sylva::studio
