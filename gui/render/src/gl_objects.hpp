// Private: owners of GL object names (buffers, vertex arrays, programs, textures, framebuffers,
// renderbuffers). Each deletes its name through the renderer's own function table when it dies,
// so the table must outlive it and the context must be current then (GlRenderer's contract).
#pragma once

#include <glad/gl.h>

#include <utility>

namespace styk::render {

// The delete call of one kind of GL object.
struct GlBufferKind {
  static void destroy(const GladGLContext& gl, GLuint name) { gl.DeleteBuffers(1, &name); }
};
struct GlVertexArrayKind {
  static void destroy(const GladGLContext& gl, GLuint name) { gl.DeleteVertexArrays(1, &name); }
};
struct GlProgramKind {
  static void destroy(const GladGLContext& gl, GLuint name) { gl.DeleteProgram(name); }
};
struct GlTextureKind {
  static void destroy(const GladGLContext& gl, GLuint name) { gl.DeleteTextures(1, &name); }
};
struct GlFramebufferKind {
  static void destroy(const GladGLContext& gl, GLuint name) { gl.DeleteFramebuffers(1, &name); }
};
struct GlRenderbufferKind {
  static void destroy(const GladGLContext& gl, GLuint name) { gl.DeleteRenderbuffers(1, &name); }
};

// A GL object name owned like a unique_ptr: movable, not copyable, 0 = none.
template <class Kind>
class GlObject {
 public:
  GlObject() = default;
  GlObject(const GladGLContext& gl, GLuint name) : gl_(&gl), name_(name) {}
  ~GlObject() { reset(); }
  GlObject(GlObject&& other) noexcept : gl_(other.gl_), name_(std::exchange(other.name_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      gl_ = other.gl_;
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  GLuint get() const { return name_; }
  void reset() {
    if (name_ != 0) Kind::destroy(*gl_, std::exchange(name_, 0));
  }

 private:
  const GladGLContext* gl_ = nullptr;
  GLuint name_ = 0;
};

using GlBuffer = GlObject<GlBufferKind>;
using GlVertexArray = GlObject<GlVertexArrayKind>;
using GlProgram = GlObject<GlProgramKind>;
using GlTexture = GlObject<GlTextureKind>;
using GlFramebuffer = GlObject<GlFramebufferKind>;
using GlRenderbuffer = GlObject<GlRenderbufferKind>;

inline GlBuffer make_buffer(const GladGLContext& gl) {
  GLuint name = 0;
  gl.GenBuffers(1, &name);
  return GlBuffer(gl, name);
}

inline GlVertexArray make_vertex_array(const GladGLContext& gl) {
  GLuint name = 0;
  gl.GenVertexArrays(1, &name);
  return GlVertexArray(gl, name);
}

inline GlTexture make_texture(const GladGLContext& gl) {
  GLuint name = 0;
  gl.GenTextures(1, &name);
  return GlTexture(gl, name);
}

inline GlFramebuffer make_framebuffer(const GladGLContext& gl) {
  GLuint name = 0;
  gl.GenFramebuffers(1, &name);
  return GlFramebuffer(gl, name);
}

inline GlRenderbuffer make_renderbuffer(const GladGLContext& gl) {
  GLuint name = 0;
  gl.GenRenderbuffers(1, &name);
  return GlRenderbuffer(gl, name);
}

}  // namespace styk::render
