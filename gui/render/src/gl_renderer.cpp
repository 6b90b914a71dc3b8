#include "styk/render/gl_renderer.hpp"

#include <glad/gl.h>

#include <cstddef>
#include <stdexcept>
#include <string>

#include "shaders.hpp"

namespace styk::render {
namespace {

GLADapiproc load_through(void* user, const char* name) {
  const auto& loader = *static_cast<const GlProcLoader*>(user);
  return reinterpret_cast<GLADapiproc>(loader(name));
}

}  // namespace

struct GlRenderer::Impl {
  GladGLContext gl{};
  GLuint scene_program = 0;
  GLuint overlay_program = 0;
  GLuint vao = 0;
  GLuint vertex_buffer = 0;
  GLuint index_buffer = 0;

  GLuint compile(GLenum kind, const char* source) {
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

  GLuint link(const char* vertex, const char* fragment) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex), fs = compile(GL_FRAGMENT_SHADER, fragment);
    const GLuint program = gl.CreateProgram();
    gl.AttachShader(program, vs);
    gl.AttachShader(program, fs);
    gl.LinkProgram(program);
    gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[2048] = {};
      gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
      throw std::runtime_error(std::string("renderer: shader program does not link: ") + log);
    }
    return program;
  }

  GLint uniform(GLuint program, const char* name) { return gl.GetUniformLocation(program, name); }

  // Uploads scene vertices and binds the Vertex layout to attributes 0..3.
  void upload_scene(const std::vector<Vertex>& vertices) {
    gl.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                  vertices.data(), GL_STREAM_DRAW);
    const GLsizei stride = sizeof(Vertex);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(offsetof(Vertex, position)));
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(offsetof(Vertex, normal)));
    gl.VertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(offsetof(Vertex, color)));
    gl.VertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(offsetof(Vertex, t)));
    for (GLuint a = 0; a < 4; ++a) gl.EnableVertexAttribArray(a);
  }

  struct Style {
    bool lit = false;
    bool use_field = false;
    bool override_color = false;
    Rgb color;
    float line_shade = 1.0f;
  };

  void set_style(const Style& style) {
    gl.Uniform1i(uniform(scene_program, "u_lit"), style.lit);
    gl.Uniform1i(uniform(scene_program, "u_use_field"), style.use_field);
    gl.Uniform1i(uniform(scene_program, "u_use_override"), style.override_color);
    gl.Uniform3f(uniform(scene_program, "u_override"), style.color.r, style.color.g, style.color.b);
    gl.Uniform1f(uniform(scene_program, "u_line_shade"), style.line_shade);
  }

  void draw_lines(const std::vector<Vertex>& lines, const Style& style) {
    if (lines.empty()) return;
    set_style(style);
    upload_scene(lines);
    gl.DrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size()));
  }

  void draw_faces(const FrameGeometry& g, const Style& style) {
    if (g.triangles.empty()) return;
    set_style(style);
    upload_scene(g.face_vertices);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                  static_cast<GLsizeiptr>(g.triangles.size() * sizeof(std::uint32_t)),
                  g.triangles.data(), GL_STREAM_DRAW);
    // Faces sit slightly behind the lines drawn on them, so edges win the depth test.
    gl.Enable(GL_POLYGON_OFFSET_FILL);
    gl.PolygonOffset(1.0f, 1.0f);
    gl.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(g.triangles.size()), GL_UNSIGNED_INT,
                    nullptr);
    gl.Disable(GL_POLYGON_OFFSET_FILL);
  }

  void draw_scene(const Frame& f) {
    const PixelRect& area = f.overlay.model;
    gl.Viewport(area.x, f.height - (area.y + area.height), area.width, area.height);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.UseProgram(scene_program);
    gl.UniformMatrix4fv(uniform(scene_program, "u_view"), 1, GL_FALSE, f.camera.view.data());
    gl.UniformMatrix4fv(uniform(scene_program, "u_projection"), 1, GL_FALSE,
                        f.camera.projection.data());
    gl.Uniform1f(uniform(scene_program, "u_point_size"), f.point_size);
    gl.Uniform1i(uniform(scene_program, "u_smooth"), f.colors.smooth);
    gl.Uniform1i(uniform(scene_program, "u_bands"), f.colors.bands);
    float palette[3 * 24] = {};
    for (int i = 0; i < f.colors.bands && i < 24; ++i) {
      const Rgb c = f.colors.band_color(i);
      palette[3 * i] = c.r, palette[3 * i + 1] = c.g, palette[3 * i + 2] = c.b;
    }
    gl.Uniform3fv(uniform(scene_program, "u_palette"), 24, palette);
    gl.BindVertexArray(vao);

    const FrameGeometry& g = f.geometry;
    const bool field = f.has_field;
    const float layer_line_shade = 0.55f;  // layer colours are light: darken them as lines
    switch (f.mode) {
      case DisplayMode::Points:
        set_style(Style{false, field, false, {}, layer_line_shade});
        upload_scene(g.points);
        gl.DrawArrays(GL_POINTS, 0, static_cast<GLsizei>(g.points.size()));
        break;
      case DisplayMode::Wireframe:
        draw_lines(g.edges, Style{false, field, false, {}, layer_line_shade});
        break;
      case DisplayMode::HiddenLine:
        draw_faces(g, Style{false, false, true, kBackground, 1.0f});
        draw_lines(g.edges, Style{false, field, false, {}, layer_line_shade});
        break;
      case DisplayMode::Shaded:
        draw_faces(g, Style{true, field, false, {}, 1.0f});
        draw_lines(g.features, Style{false, false, true, kInk, 1.0f});
        break;
      case DisplayMode::ShadedEdges:
        draw_faces(g, Style{true, field, false, {}, 1.0f});
        draw_lines(g.edges, Style{false, false, true, kInk, 1.0f});
        break;
    }
    draw_lines(g.outline, Style{false, false, true, kOutline, 1.0f});
  }

  void draw_overlay(const Frame& f) {
    const std::vector<OverlayVertex>& v = f.overlay.triangles;
    if (v.empty()) return;
    gl.Viewport(0, 0, f.width, f.height);
    gl.Disable(GL_DEPTH_TEST);
    gl.UseProgram(overlay_program);
    gl.Uniform2f(uniform(overlay_program, "u_size"), float(f.width), float(f.height));
    gl.BindVertexArray(vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(OverlayVertex)),
                  v.data(), GL_STREAM_DRAW);
    const GLsizei stride = sizeof(OverlayVertex);
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(offsetof(OverlayVertex, x)));
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(offsetof(OverlayVertex, color)));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
    gl.DisableVertexAttribArray(2);
    gl.DisableVertexAttribArray(3);
    gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size()));
  }
};

GlRenderer::GlRenderer(const GlProcLoader& loader) : impl_(std::make_unique<Impl>()) {
  const int version =
      gladLoadGLContextUserPtr(&impl_->gl, load_through, const_cast<GlProcLoader*>(&loader));
  if (version == 0 || GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
    throw std::runtime_error("renderer: needs an OpenGL 3.3 core context (got " +
                             std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                             std::to_string(GLAD_VERSION_MINOR(version)) + ")");
  Impl& r = *impl_;
  r.scene_program = r.link(shaders::kSceneVertex, shaders::kSceneFragment);
  r.overlay_program = r.link(shaders::kOverlayVertex, shaders::kOverlayFragment);
  r.gl.GenVertexArrays(1, &r.vao);
  r.gl.GenBuffers(1, &r.vertex_buffer);
  r.gl.GenBuffers(1, &r.index_buffer);
}

GlRenderer::~GlRenderer() {
  Impl& r = *impl_;
  if (r.gl.DeleteBuffers) {
    r.gl.DeleteBuffers(1, &r.vertex_buffer);
    r.gl.DeleteBuffers(1, &r.index_buffer);
    r.gl.DeleteVertexArrays(1, &r.vao);
    r.gl.DeleteProgram(r.scene_program);
    r.gl.DeleteProgram(r.overlay_program);
  }
}

void GlRenderer::draw(const Frame& frame) {
  Impl& r = *impl_;
  r.gl.Disable(GL_MULTISAMPLE);  // deterministic pixels: no multisampling, no blending
  r.gl.Disable(GL_BLEND);
  r.gl.Viewport(0, 0, frame.width, frame.height);
  r.gl.ClearColor(kBackground.r, kBackground.g, kBackground.b, 1.0f);
  r.gl.ClearDepth(1.0);
  r.gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  r.gl.Enable(GL_PROGRAM_POINT_SIZE);
  r.draw_scene(frame);
  r.draw_overlay(frame);
}

Image GlRenderer::read_pixels(int width, int height) {
  Impl& r = *impl_;
  r.gl.Finish();
  Image bottom_up(width, height);
  r.gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  r.gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.rgba.data());
  // GL rows start at the bottom; pictures start at the top.
  Image image(width, height);
  const std::size_t row = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(bottom_up.rgba.data() + std::size_t(height - 1 - y) * row, row,
                image.rgba.data() + std::size_t(y) * row);
  return image;
}

}  // namespace styk::render
