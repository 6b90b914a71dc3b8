// Draws a Frame with OpenGL 3.3 core into the framebuffer bound in the current context. The GL
// functions come through a glad2 loader (multi-context build: the function table belongs to this
// object, not to a global), fed by the caller's getProcAddress: OSMesaGetProcAddress headless,
// QOpenGLContext::getProcAddress in the desktop program. No GL or window type appears here.
#pragma once

#include <functional>
#include <memory>

#include "styk/render/frame.hpp"
#include "styk/render/image.hpp"

namespace styk::render {

using GlProcLoader = std::function<void*(const char* name)>;

class GlRenderer {
 public:
  // Loads the GL 3.3 core functions and compiles the shaders: the context must be current.
  // Throws std::runtime_error when the context is older than 3.3 or a shader does not compile.
  explicit GlRenderer(const GlProcLoader& loader);
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  // Draws the frame into a framebuffer of frame.width x frame.height pixels.
  void draw(const Frame& frame);
  // Waits for the GL and reads the framebuffer, rows top-down.
  Image read_pixels(int width, int height);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace styk::render
