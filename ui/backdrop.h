// The viewport background: a vertical gradient, dark grey-blue, lighter at the horizon side
// (top) so a brown tree reads clearly against it. Drawn first, without touching depth.
#pragma once

#include "ui/gl_program.h"

namespace sylva::studio {

class Backdrop {
  public:
    Backdrop();  // needs a current GL 3.3 context
    ~Backdrop();
    Backdrop(const Backdrop&) = delete;
    Backdrop& operator=(const Backdrop&) = delete;

    void draw() const;

  private:
    GlProgram program_;
    GLuint vertex_array_ = 0;  // empty: core profile needs one bound to draw at all
};

}  // namespace sylva::studio
