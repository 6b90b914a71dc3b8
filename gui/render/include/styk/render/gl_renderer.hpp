// Draws a Frame with OpenGL 3.3 core into the framebuffer bound in the current context. The GL
// functions come through a glad2 loader (multi-context build: the function table belongs to this
// object, not to a global), fed by the caller's getProcAddress: OSMesaGetProcAddress headless,
// QOpenGLContext::getProcAddress in the desktop program. No GL or window type appears here. The
// GL objects (programs, buffers, vertex arrays) belong to the context current at construction;
// it must also be current whenever a member is called, destruction included.
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

  // One picture: uploads frame.geometry (as set_geometry) and draws it with the frame's view,
  // into a framebuffer of frame.width x frame.height pixels (styk render, animation frames).
  void draw(const Frame& frame);

  // Retained drawing, for a view that changes more often than the model (orbit, pan, zoom,
  // overlay): set_geometry() copies the vertex arrays into GL buffers that stay until the next
  // set_geometry(); draw_view() draws them with the view's camera, overlay, mode and colour
  // scale without sending any vertex of the model again. The caller uploads again whenever the
  // geometry changes (new field, colours, deformation, layers); before the first upload
  // draw_view() draws the overlay on an empty scene.
  void set_geometry(const FrameGeometry& geometry);
  void draw_view(const FrameView& view);

  // Waits for the GL and reads the framebuffer, rows top-down.
  Image read_pixels(int width, int height);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace styk::render
