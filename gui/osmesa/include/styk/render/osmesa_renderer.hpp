// Headless drawing: an OSMesa (llvmpipe) OpenGL 3.3 core context with its own off-screen colour
// and depth buffer, and the GlRenderer that draws into it. Kept in its own library so that no
// executable mixes libOSMesa's GL symbols with another GL library by accident.
#pragma once

#include <memory>

#include "styk/render/frame.hpp"
#include "styk/render/image.hpp"

namespace styk::render {

class OsmesaRenderer {
 public:
  // Creates the context and a width x height buffer. Throws std::runtime_error when OSMesa cannot
  // give a 3.3 core context.
  OsmesaRenderer(int width, int height);
  ~OsmesaRenderer();
  OsmesaRenderer(const OsmesaRenderer&) = delete;
  OsmesaRenderer& operator=(const OsmesaRenderer&) = delete;

  // Draws the frame (resizing the buffer to the frame's size if needed) and returns the picture.
  Image render(const Frame& frame);

  // Retained drawing (GlRenderer::set_geometry / draw_view): upload the geometry once, then
  // picture it under as many views as wanted (orbits, views of one model).
  void set_geometry(const FrameGeometry& geometry);
  Image render_view(const FrameView& view);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace styk::render
