// Draws line segments or points in one colour: the skeleton (the turtle graphic of Heuer
// 2022, table 4.4) over or through the meshes, the colonization envelope and its points.
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

    // Pairs of points: (points[0], points[1]) is the first segment, and so on. For
    // draw_points, any number of points.
    void upload(std::span<const glm::vec3> points);
    // Drawn without depth test, so the skeleton shows through the bark.
    void draw(const glm::mat4& view, const glm::mat4& projection, const glm::vec3& color) const;
    // Every uploaded point as a square dot `size` pixels wide, also without depth test.
    void draw_points(const glm::mat4& view, const glm::mat4& projection, const glm::vec3& color,
                     float size) const;

  private:
    void draw_as(GLenum mode, const glm::mat4& view, const glm::mat4& projection,
                 const glm::vec3& color) const;

    GlProgram program_;
    PositionBuffer lines_;
};

}  // namespace sylva::studio
