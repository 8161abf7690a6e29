// Draws line segments in one colour: the skeleton (the turtle graphic of seed 001's table
// 4.4) over or through the meshes.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <span>

#include "ui/gl_program.h"
#include "ui/position_buffer.h"

namespace sylva::studio {

class LineRenderer {
  public:
    LineRenderer();  // needs a current GL 3.3 context

    // Pairs of points: (points[0], points[1]) is the first segment, and so on.
    void upload(std::span<const glm::vec3> points);
    // Drawn without depth test, so the skeleton shows through the bark.
    void draw(const glm::mat4& view, const glm::mat4& projection, const glm::vec3& color) const;

  private:
    GlProgram program_;
    PositionBuffer lines_;
};

}  // namespace sylva::studio
