// Private: compiling and linking GLSL programs through the renderer's function table.
#pragma once

#include "gl_objects.hpp"

namespace styk::render {

// A program of a vertex and a fragment stage, and a geometry stage when `geometry` is given.
// Throws std::runtime_error with the GL's log when a stage does not compile or the program does
// not link.
GlProgram link_program(const GladGLContext& gl, const char* vertex, const char* fragment,
                       const char* geometry = nullptr);

}  // namespace styk::render
