// Private: the off-screen framebuffers of a picture drawn with multisampling or with scene labels.
// The scene is drawn into a multisampled colour + depth target (samples > 1), resolved into a
// single-sampled colour + depth target (the depth the scene labels are tested against), then
// copied to the caller's framebuffer, where the overlay is drawn on top with exact pixels. With
// one sample the scene is drawn straight into the single-sampled target.
#pragma once

#include <vector>

#include "gl_objects.hpp"
#include "styk/render/overlay.hpp"

namespace styk::render {

class OffscreenTargets {
 public:
  explicit OffscreenTargets(const GladGLContext& gl);

  // Sizes the targets for a width x height picture with `samples` per pixel (clamped to the GL's
  // GL_MAX_SAMPLES; 1 = none), keeping them when nothing changed.
  void prepare(int width, int height, int samples);
  int samples() const { return samples_; }
  // Binds the target the scene is drawn into (for drawing and reading).
  void bind_scene() const;
  // Multisampled colour and depth -> single-sampled (nothing to do with one sample).
  void resolve() const;
  // Window depth (0 near .. 1 far) of `area` of the resolved picture, rows bottom-up as the GL
  // stores them; `picture_height` places the area (top-left origin) in GL rows.
  std::vector<float> read_depth(const PixelRect& area, int picture_height) const;
  // Copies the resolved colour to framebuffer `target` and leaves it bound for drawing and
  // reading.
  void copy_to(GLuint target) const;

 private:
  const GladGLContext& gl_;
  int width_ = 0, height_ = 0, samples_ = 0;
  GlFramebuffer multisampled_, resolved_;
  GlRenderbuffer ms_colour_, ms_depth_, colour_, depth_;
};

}  // namespace styk::render
