#include "gl_program.hpp"

#include <stdexcept>
#include <string>

namespace styk::render {
namespace {

GLuint compile(const GladGLContext& gl, GLenum kind, const char* source) {
  const GLuint shader = gl.CreateShader(kind);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    gl.DeleteShader(shader);
    throw std::runtime_error(std::string("renderer: shader does not compile: ") + log);
  }
  return shader;
}

}  // namespace

GlProgram link_program(const GladGLContext& gl, const char* vertex, const char* fragment,
                       const char* geometry) {
  const GLuint vs = compile(gl, GL_VERTEX_SHADER, vertex);
  const GLuint fs = compile(gl, GL_FRAGMENT_SHADER, fragment);
  const GLuint gs = geometry ? compile(gl, GL_GEOMETRY_SHADER, geometry) : 0;
  GlProgram program(gl, gl.CreateProgram());
  gl.AttachShader(program.get(), vs);
  gl.AttachShader(program.get(), fs);
  if (gs) gl.AttachShader(program.get(), gs);
  gl.LinkProgram(program.get());
  gl.DeleteShader(vs);
  gl.DeleteShader(fs);
  if (gs) gl.DeleteShader(gs);
  GLint ok = 0;
  gl.GetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    gl.GetProgramInfoLog(program.get(), sizeof log, nullptr, log);
    throw std::runtime_error(std::string("renderer: shader program does not link: ") + log);
  }
  return program;
}

}  // namespace styk::render
