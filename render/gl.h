#pragma once
// OpenGL 3.3 core entry points. On Linux, Mesa's libGL exports every core function, so the
// prototypes are declared directly (no loader library needed); GLFW creates the context.

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
