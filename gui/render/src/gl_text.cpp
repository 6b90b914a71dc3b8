#include "gl_text.hpp"

#include <cstddef>

#include "gl_program.hpp"
#include "shaders.hpp"

namespace styk::render {

GlText::GlText(const GladGLContext& gl)
    : gl_(gl),
      program_(link_program(gl, shaders::kTextVertex, shaders::kTextFragment)),
      array_(make_vertex_array(gl)),
      buffer_(make_buffer(gl)),
      texture_(make_texture(gl)) {
  size_uniform_ = gl.GetUniformLocation(program_.get(), "u_size");
  atlas_uniform_ = gl.GetUniformLocation(program_.get(), "u_atlas");
  gl.BindVertexArray(array_.get());
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer_.get());
  const GLsizei stride = sizeof(TextVertex);
  gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<void*>(offsetof(TextVertex, x)));
  gl.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<void*>(offsetof(TextVertex, u)));
  gl.VertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<void*>(offsetof(TextVertex, color)));
  for (GLuint a = 0; a < 3; ++a) gl.EnableVertexAttribArray(a);
  gl.BindVertexArray(0);
  gl.BindTexture(GL_TEXTURE_2D, texture_.get());
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.BindTexture(GL_TEXTURE_2D, 0);
}

void GlText::upload(const std::shared_ptr<const AlphaImage>& atlas) {
  if (atlas == uploaded_) return;
  gl_.BindTexture(GL_TEXTURE_2D, texture_.get());
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas->width, atlas->height, 0, GL_RED, GL_UNSIGNED_BYTE,
                 atlas->alpha.data());
  uploaded_ = atlas;
}

void GlText::draw(const std::vector<TextVertex>& quads,
                  const std::shared_ptr<const AlphaImage>& atlas, int width, int height) {
  if (quads.empty() || !atlas || atlas->width == 0) return;
  upload(atlas);
  gl_.Viewport(0, 0, width, height);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Enable(GL_BLEND);
  // Colour blended by coverage; the picture's alpha stays opaque.
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  gl_.UseProgram(program_.get());
  gl_.Uniform2f(size_uniform_, float(width), float(height));
  gl_.ActiveTexture(GL_TEXTURE0);
  gl_.BindTexture(GL_TEXTURE_2D, texture_.get());
  gl_.Uniform1i(atlas_uniform_, 0);
  gl_.BindVertexArray(array_.get());
  gl_.BindBuffer(GL_ARRAY_BUFFER, buffer_.get());
  // Small and rebuilt per view (legend, title, labels): streamed every frame.
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(quads.size() * sizeof(TextVertex)),
                 quads.data(), GL_STREAM_DRAW);
  gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(quads.size()));
  gl_.Disable(GL_BLEND);
  gl_.BindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace styk::render
