// A vertex array with one buffer of vec3 positions at attribute 0: what the line drawers
// (ground grid, skeleton) upload and draw.
#pragma once

#include <glm/vec3.hpp>
#include <span>

#include "ui/gl.h"

namespace sylva::studio {

class PositionBuffer {
  public:
    PositionBuffer();  // needs a current GL 3.3 context
    ~PositionBuffer();
    PositionBuffer(const PositionBuffer&) = delete;
    PositionBuffer& operator=(const PositionBuffer&) = delete;

    void upload(std::span<const glm::vec3> points);
    GLsizei count() const { return count_; }
    // Draws every point as `mode` (GL_LINES ...) with the program already in use.
    void draw(GLenum mode) const;

  private:
    GLuint vertex_array_ = 0;
    GLuint vertex_buffer_ = 0;
    GLsizei count_ = 0;
};

}  // namespace sylva::studio
