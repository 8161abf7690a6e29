// A linked GLSL program that owns its GL object. Compile or link errors throw with the
// driver's log, prefixed by the program's name, so a shader typo reads as one clear message.
#pragma once

#include "ui/gl.h"

namespace sylva::studio {

class GlProgram {
  public:
    // Needs a current GL 3.3 context. Throws std::runtime_error on a compile or link error.
    GlProgram(const char* name, const char* vertex_source, const char* fragment_source);
    ~GlProgram();
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;

    GLuint id() const { return id_; }
    // Location of a uniform; -1 (ignored by glUniform*) when the driver optimised it out.
    GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

  private:
    GLuint id_ = 0;
};

}  // namespace sylva::studio
