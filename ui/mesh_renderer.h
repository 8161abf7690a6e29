// Draws a sylva::Mesh flat-shaded, the low-poly look: each fragment's normal is the cross
// product of its position's screen-space derivatives, i.e. its triangle's face normal, so the
// indexed mesh is uploaded as is, without a vertex copy per face.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/mesh.h"
#include "ui/gl_program.h"

namespace sylva::studio {

class MeshRenderer {
  public:
    MeshRenderer();  // needs a current GL 3.3 context
    ~MeshRenderer();
    MeshRenderer(const MeshRenderer&) = delete;
    MeshRenderer& operator=(const MeshRenderer&) = delete;

    // Replaces the GPU copy. Triangles must be counter-clockwise seen from where they show:
    // back faces are culled (leaves carry both windings).
    void upload(const Mesh& mesh);

    // `albedo` is in linear RGB; the output is gamma-encoded for an 8-bit framebuffer.
    void draw(const glm::mat4& view, const glm::mat4& projection, const glm::vec3& albedo) const;
    // The triangle edges in one unlit colour, drawn over the faces.
    void draw_wireframe(const glm::mat4& view, const glm::mat4& projection,
                        const glm::vec3& color) const;

  private:
    void draw_with(const glm::mat4& view, const glm::mat4& projection, const glm::vec3& albedo,
                   bool unlit) const;

    GlProgram program_;
    GLuint vertex_array_ = 0;
    GLuint vertex_buffer_ = 0;
    GLuint index_buffer_ = 0;
    GLsizei index_count_ = 0;
};

}  // namespace sylva::studio
