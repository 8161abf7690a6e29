#include "ui/mesh_renderer.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

namespace sylva::studio {
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view;
uniform mat4 u_projection;
out vec3 v_view_position;
void main() {
    vec4 p = u_view * vec4(a_position, 1.0);
    v_view_position = p.xyz;
    gl_Position = u_projection * p;
}
)";

// Lighting is in view space, like a studio light rig that moves with the camera: the side
// the artist looks at is always lit. A warm key from the upper left, a sky/ground hemisphere
// fill that keeps the shadow side readable, and a faint cool rim to separate the silhouette
// from the dark background.
constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 v_view_position;
uniform vec3 u_albedo;
uniform vec3 u_up;  // world +Y in view space
uniform bool u_unlit;  // the wireframe overlay: plain colour
out vec4 frag_color;
void main() {
    if (u_unlit) {
        frag_color = vec4(pow(u_albedo, vec3(1.0 / 2.2)), 1.0);
        return;
    }
    vec3 n = normalize(cross(dFdx(v_view_position), dFdy(v_view_position)));
    vec3 to_eye = normalize(-v_view_position);
    vec3 key_direction = normalize(vec3(-0.5, 0.6, 0.65));
    float key = max(dot(n, key_direction), 0.0);
    float sky = 0.5 + 0.5 * dot(n, u_up);
    vec3 fill = mix(vec3(0.10, 0.09, 0.08), vec3(0.30, 0.32, 0.36), sky);
    float rim = pow(1.0 - max(dot(n, to_eye), 0.0), 3.0);
    vec3 linear = u_albedo * (fill + vec3(1.15, 1.08, 0.98) * key) + 0.06 * rim * vec3(0.7, 0.8, 1.0);
    frag_color = vec4(pow(clamp(linear, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
)";

}  // namespace

MeshRenderer::MeshRenderer() : program_("mesh", kVertexShader, kFragmentShader) {
    glGenVertexArrays(1, &vertex_array_);
    glGenBuffers(1, &vertex_buffer_);
    glGenBuffers(1, &index_buffer_);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);  // recorded in the vertex array
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindVertexArray(0);
}

MeshRenderer::~MeshRenderer() {
    glDeleteBuffers(1, &index_buffer_);
    glDeleteBuffers(1, &vertex_buffer_);
    glDeleteVertexArrays(1, &vertex_array_);
}

void MeshRenderer::upload(const Mesh& mesh) {
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
    static_assert(sizeof(mesh.triangles[0]) == 3 * sizeof(std::uint32_t));
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.positions.size() * sizeof(glm::vec3)),
                 mesh.positions.data(), GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.triangles.size() * sizeof(mesh.triangles[0])),
                 mesh.triangles.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    index_count_ = static_cast<GLsizei>(3 * mesh.triangles.size());
}

void MeshRenderer::draw_wireframe(const glm::mat4& view, const glm::mat4& projection,
                                  const glm::vec3& color) const {
    if (index_count_ == 0) return;
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(-1.0f, -1.0f);  // the lines win the depth test against their own faces
    draw_with(view, projection, color, true);
    glDisable(GL_POLYGON_OFFSET_LINE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

void MeshRenderer::draw(const glm::mat4& view, const glm::mat4& projection,
                        const glm::vec3& albedo) const {
    draw_with(view, projection, albedo, false);
}

void MeshRenderer::draw_with(const glm::mat4& view, const glm::mat4& projection,
                             const glm::vec3& albedo, bool unlit) const {
    if (index_count_ == 0) return;
    glm::vec3 up = glm::mat3(view) * glm::vec3(0.0f, 1.0f, 0.0f);
    glUseProgram(program_.id());
    glUniformMatrix4fv(program_.uniform("u_view"), 1, GL_FALSE, glm::value_ptr(view));
    glUniformMatrix4fv(program_.uniform("u_projection"), 1, GL_FALSE, glm::value_ptr(projection));
    glUniform3fv(program_.uniform("u_albedo"), 1, glm::value_ptr(albedo));
    glUniform3fv(program_.uniform("u_up"), 1, glm::value_ptr(up));
    glUniform1i(program_.uniform("u_unlit"), unlit ? 1 : 0);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glBindVertexArray(vertex_array_);
    glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glDisable(GL_CULL_FACE);
}

}  // namespace sylva::studio
