#include "gl_targets.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace styk::render {
namespace {

void storage(const GladGLContext& gl, GLuint renderbuffer, int samples, GLenum format, int width,
             int height) {
  gl.BindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
  if (samples > 1)
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  else
    gl.RenderbufferStorage(GL_RENDERBUFFER, format, width, height);
}

void attach(const GladGLContext& gl, GLuint framebuffer, GLuint colour, GLuint depth) {
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("renderer: off-screen framebuffer incomplete (status " +
                             std::to_string(status) + ")");
}

}  // namespace

OffscreenTargets::OffscreenTargets(const GladGLContext& gl) : gl_(gl) {}

void OffscreenTargets::prepare(int width, int height, int samples) {
  GLint most = 1;
  gl_.GetIntegerv(GL_MAX_SAMPLES, &most);
  samples = std::clamp(samples, 1, std::max(1, int(most)));
  if (width == width_ && height == height_ && samples == samples_) return;
  width_ = width, height_ = height, samples_ = samples;
  // Depth is 24 bits in both targets: a multisampled depth blit needs equal formats.
  if (!resolved_.get()) {
    resolved_ = make_framebuffer(gl_);
    colour_ = make_renderbuffer(gl_);
    depth_ = make_renderbuffer(gl_);
  }
  storage(gl_, colour_.get(), 1, GL_RGBA8, width, height);
  storage(gl_, depth_.get(), 1, GL_DEPTH_COMPONENT24, width, height);
  attach(gl_, resolved_.get(), colour_.get(), depth_.get());
  if (samples > 1) {
    if (!multisampled_.get()) {
      multisampled_ = make_framebuffer(gl_);
      ms_colour_ = make_renderbuffer(gl_);
      ms_depth_ = make_renderbuffer(gl_);
    }
    storage(gl_, ms_colour_.get(), samples, GL_RGBA8, width, height);
    storage(gl_, ms_depth_.get(), samples, GL_DEPTH_COMPONENT24, width, height);
    attach(gl_, multisampled_.get(), ms_colour_.get(), ms_depth_.get());
  }
  gl_.BindRenderbuffer(GL_RENDERBUFFER, 0);
}

void OffscreenTargets::bind_scene() const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? multisampled_.get() : resolved_.get());
}

void OffscreenTargets::resolve() const {
  if (samples_ <= 1) return;
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_.get());
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_.get());
  gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_,
                      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

std::vector<float> OffscreenTargets::read_depth(const PixelRect& area, int picture_height) const {
  std::vector<float> depth(std::size_t(std::max(0, area.width)) * std::max(0, area.height), 1.0f);
  if (depth.empty()) return depth;
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, resolved_.get());
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl_.ReadPixels(area.x, picture_height - (area.y + area.height), area.width, area.height,
                 GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  return depth;
}

void OffscreenTargets::copy_to(GLuint target) const {
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, resolved_.get());
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
  gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, target);
}

}  // namespace styk::render
