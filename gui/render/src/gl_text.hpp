// Private: the text of the overlay on the GL side: the glyph atlas as an R8 texture (uploaded
// again only when a picture brings another atlas snapshot) and the program that blends glyph
// quads over the picture.
#pragma once

#include <memory>
#include <vector>

#include "gl_objects.hpp"
#include "styk/render/font.hpp"

namespace styk::render {

class GlText {
 public:
  // Compiles the program and makes the buffers: the context must be current.
  explicit GlText(const GladGLContext& gl);

  // Draws the quads over the bound framebuffer, whose whole picture is width x height pixels.
  void draw(const std::vector<TextVertex>& quads, const std::shared_ptr<const AlphaImage>& atlas,
            int width, int height);

 private:
  void upload(const std::shared_ptr<const AlphaImage>& atlas);

  const GladGLContext& gl_;
  GlProgram program_;
  GLint size_uniform_ = -1, atlas_uniform_ = -1;
  GlVertexArray array_;
  GlBuffer buffer_;
  GlTexture texture_;
  std::shared_ptr<const AlphaImage> uploaded_;  // held, so its address is never reused
};

}  // namespace styk::render
