// The one place sylva-studio includes OpenGL. Mesa's libGL (and glvnd's libOpenGL) export
// every GL 3.3 core entry point, so prototypes are enough: no loader and no function-pointer
// globals. The core libraries never include this.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
