#include "styk/render/osmesa_renderer.hpp"

#include <GL/osmesa.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "styk/render/gl_renderer.hpp"

namespace styk::render {

struct OsmesaRenderer::Impl {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> buffer;  // OSMesa's colour buffer (RGBA, rows bottom-up)
  int width = 0;
  int height = 0;
  std::unique_ptr<GlRenderer> renderer;

  void make_current(int w, int h) {
    buffer.assign(static_cast<std::size_t>(w) * h * 4, 0);
    if (!OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, w, h))
      throw std::runtime_error("OSMesa: cannot bind a " + std::to_string(w) + "x" +
                               std::to_string(h) + " buffer");
    width = w, height = h;
  }

  // Another OsmesaRenderer (or anyone) may have made its own context current since: GL calls go
  // to the current context, so take ours back first, at the wanted size.
  void ensure_current(int w, int h) {
    if (w != width || h != height)
      make_current(w, h);
    else if (OSMesaGetCurrentContext() != context &&
             !OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, w, h))
      throw std::runtime_error("OSMesa: cannot make the context current again");
  }
};

OsmesaRenderer::OsmesaRenderer(int width, int height) : impl_(std::make_unique<Impl>()) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  impl_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!impl_->context) throw std::runtime_error("OSMesa: cannot create an OpenGL 3.3 core context");
  try {
    impl_->make_current(width, height);
    impl_->renderer = std::make_unique<GlRenderer>(
        [](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); });
  } catch (...) {
    OSMesaDestroyContext(impl_->context);
    throw;
  }
}

OsmesaRenderer::~OsmesaRenderer() {
  if (OSMesaGetCurrentContext() != impl_->context)  // its GL objects die in their own context
    OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, impl_->width,
                      impl_->height);
  impl_->renderer.reset();
  OSMesaDestroyContext(impl_->context);
}

Image OsmesaRenderer::render(const Frame& frame) {
  set_geometry(frame.geometry);
  return render_view(frame);
}

void OsmesaRenderer::set_geometry(const FrameGeometry& geometry) {
  impl_->ensure_current(impl_->width, impl_->height);
  impl_->renderer->set_geometry(geometry);
}

Image OsmesaRenderer::render_view(const FrameView& view) {
  // Rebinding the context to a new buffer keeps its GL objects (the retained geometry).
  impl_->ensure_current(view.width, view.height);
  impl_->renderer->draw_view(view);
  return impl_->renderer->read_pixels(view.width, view.height);
}

}  // namespace styk::render
