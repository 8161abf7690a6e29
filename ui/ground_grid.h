// A ground grid on the plane y = 0 (Y up, meters) that gives the tree scale and a floor.
// Lines fade out towards the rim so the grid has no hard edge.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "ui/gl_program.h"
#include "ui/position_buffer.h"

namespace sylva::studio {

class GroundGrid {
  public:
    GroundGrid();  // needs a current GL 3.3 context

    // Lays out lines every `cell` meters around `centre` (its y is ignored) out to about
    // `radius` meters. Both must be positive.
    void layout(glm::vec3 centre, float radius, float cell);

    // Draws over what is there, depth-tested but not depth-writing, alpha-blended.
    void draw(const glm::mat4& view, const glm::mat4& projection) const;

  private:
    GlProgram program_;
    PositionBuffer lines_;
    glm::vec3 centre_{0.0f};
    float radius_ = 1.0f;
};

// A round grid spacing (0.1, 0.25, 0.5, 1, 2.5, 5 ... meters) giving roughly ten cells over
// `size` meters.
float grid_cell_for(float size);

}  // namespace sylva::studio
