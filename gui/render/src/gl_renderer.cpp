#include "styk/render/gl_renderer.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

#include "gl_objects.hpp"
#include "gl_program.hpp"
#include "gl_targets.hpp"
#include "gl_text.hpp"
#include "gpu_geometry.hpp"
#include "label_placement.hpp"
#include "shaders.hpp"

namespace styk::render {
namespace {

GLADapiproc load_through(void* user, const char* name) {
  const auto& loader = *static_cast<const GlProcLoader*>(user);
  return reinterpret_cast<GLADapiproc>(loader(name));
}

// The uniforms of the scene and bar programs, looked up once after linking (-1 for those a
// program does not have: setting them does nothing).
struct SceneUniforms {
  GLint view, projection, point_size, smooth, bands, palette;
  GLint lit, use_field, use_override, override_color, line_shade, round_points;
  GLint viewport, line_width;  // bar program only

  SceneUniforms(const GladGLContext& gl, GLuint p)
      : view(gl.GetUniformLocation(p, "u_view")),
        projection(gl.GetUniformLocation(p, "u_projection")),
        point_size(gl.GetUniformLocation(p, "u_point_size")),
        smooth(gl.GetUniformLocation(p, "u_smooth")),
        bands(gl.GetUniformLocation(p, "u_bands")),
        palette(gl.GetUniformLocation(p, "u_palette")),
        lit(gl.GetUniformLocation(p, "u_lit")),
        use_field(gl.GetUniformLocation(p, "u_use_field")),
        use_override(gl.GetUniformLocation(p, "u_use_override")),
        override_color(gl.GetUniformLocation(p, "u_override")),
        line_shade(gl.GetUniformLocation(p, "u_line_shade")),
        round_points(gl.GetUniformLocation(p, "u_round_points")),
        viewport(gl.GetUniformLocation(p, "u_viewport")),
        line_width(gl.GetUniformLocation(p, "u_line_width")) {}
};

// How one primitive list is coloured.
struct Style {
  bool lit = false;
  bool use_field = false;
  bool override_color = false;
  Rgb color;
  float line_shade = 1.0f;
};

}  // namespace

struct GlRenderer::Impl {
  // Declared first: the GL objects below are deleted through it, so it must die last.
  GladGLContext gl{};
  GlProgram scene_program;
  GlProgram overlay_program;
  GlProgram bar_program;  // line elements, widened to quads by a geometry stage
  std::optional<SceneUniforms> scene_uniforms;
  std::optional<SceneUniforms> bar_uniforms;
  GLint overlay_size = -1;
  std::optional<GpuGeometry> geometry;  // the retained vertex arrays of the model
  GlVertexArray overlay_array;
  GlBuffer overlay_buffer;
  std::optional<GlText> text;
  std::optional<OffscreenTargets> targets;

  void init() {
    scene_program = link_program(gl, shaders::kSceneVertex, shaders::kSceneFragment);
    overlay_program = link_program(gl, shaders::kOverlayVertex, shaders::kOverlayFragment);
    bar_program =
        link_program(gl, shaders::kBarVertex, shaders::kSceneFragment, shaders::kBarGeometry);
    text.emplace(gl);
    targets.emplace(gl);
    scene_uniforms.emplace(gl, scene_program.get());
    bar_uniforms.emplace(gl, bar_program.get());
    overlay_size = gl.GetUniformLocation(overlay_program.get(), "u_size");
    geometry.emplace(gl);
    overlay_array = make_vertex_array(gl);
    overlay_buffer = make_buffer(gl);
    gl.BindVertexArray(overlay_array.get());
    gl.BindBuffer(GL_ARRAY_BUFFER, overlay_buffer.get());
    const GLsizei stride = sizeof(OverlayVertex);
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(offsetof(OverlayVertex, x)));
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(offsetof(OverlayVertex, color)));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
    gl.BindVertexArray(0);
  }

  void set_style(const SceneUniforms& u, const Style& style) {
    gl.Uniform1i(u.lit, style.lit);
    gl.Uniform1i(u.use_field, style.use_field);
    gl.Uniform1i(u.use_override, style.override_color);
    gl.Uniform3f(u.override_color, style.color.r, style.color.g, style.color.b);
    gl.Uniform1f(u.line_shade, style.line_shade);
    gl.Uniform1i(u.round_points, 0);
  }

  // Integration points as round dots of their value's colour, depth-tested among themselves and
  // against the faces drawn (the see-through modes draw none).
  void draw_ip_points(const FrameView& f) {
    if (geometry->empty(Primitives::IpPoints)) return;
    set_style(*scene_uniforms, Style{false, true, false, {}, 1.0f});
    gl.Uniform1i(scene_uniforms->round_points, 1);
    gl.Uniform1f(scene_uniforms->point_size, f.ip_point_size);
    geometry->draw(Primitives::IpPoints);
    gl.Uniform1i(scene_uniforms->round_points, 0);
    gl.Uniform1f(scene_uniforms->point_size, f.point_size);
  }

  void draw_lines(Primitives lines, const Style& style) {
    if (geometry->empty(lines)) return;
    set_style(*scene_uniforms, style);
    geometry->draw(lines);
  }

  void draw_faces(const Style& style) {
    if (geometry->empty(Primitives::Faces)) return;
    set_style(*scene_uniforms, style);
    // A closed skin seen from outside: its back faces are all hidden, so the rasteriser need not
    // fill them (about half the triangles). Triangles are clockwise seen from outside.
    if (geometry->closed()) {
      gl.Enable(GL_CULL_FACE);
      gl.FrontFace(GL_CW);
      gl.CullFace(GL_BACK);
    }
    // Faces sit slightly behind the lines drawn on them, so edges win the depth test.
    gl.Enable(GL_POLYGON_OFFSET_FILL);
    gl.PolygonOffset(1.0f, 1.0f);
    geometry->draw(Primitives::Faces);
    gl.Disable(GL_POLYGON_OFFSET_FILL);
    gl.Disable(GL_CULL_FACE);
    gl.FrontFace(GL_CCW);  // the GL default, for whoever shares the context (Qt)
  }

  // The line elements as quads of f.bar_width pixels in the model area, with their own program
  // (the scene program is in use again afterwards).
  void draw_bars(const FrameView& f, const Style& style) {
    if (geometry->empty(Primitives::Bars)) return;
    gl.UseProgram(bar_program.get());
    const SceneUniforms& u = *bar_uniforms;
    set_view_uniforms(u, f);
    gl.Uniform2f(u.viewport, float(f.overlay.model.width), float(f.overlay.model.height));
    gl.Uniform1f(u.line_width, f.bar_width);
    set_style(u, style);
    geometry->draw(Primitives::Bars);
    gl.UseProgram(scene_program.get());
  }

  // Camera and colour scale, for the program in use.
  void set_view_uniforms(const SceneUniforms& u, const FrameView& f) {
    gl.UniformMatrix4fv(u.view, 1, GL_FALSE, f.camera.view.data());
    gl.UniformMatrix4fv(u.projection, 1, GL_FALSE, f.camera.projection.data());
    gl.Uniform1f(u.point_size, f.point_size);
    gl.Uniform1i(u.smooth, f.colors.smooth);
    gl.Uniform1i(u.bands, f.colors.bands);
    float palette[3 * kMaxBands] = {};
    for (int i = 0; i < std::min(f.colors.bands, kMaxBands); ++i) {
      const Rgb c = f.colors.band_color(i);
      palette[3 * i] = c.r, palette[3 * i + 1] = c.g, palette[3 * i + 2] = c.b;
    }
    gl.Uniform3fv(u.palette, kMaxBands, palette);
  }

  void draw_scene(const FrameView& f) {
    const PixelRect& area = f.overlay.model;
    gl.Viewport(area.x, f.height - (area.y + area.height), area.width, area.height);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.UseProgram(scene_program.get());
    set_view_uniforms(*scene_uniforms, f);

    const bool field = f.has_field;
    const float layer_line_shade = 0.55f;  // layer colours are light: darken them as lines
    switch (f.mode) {
      case DisplayMode::Points:
        draw_lines(Primitives::Points, Style{false, field, false, {}, layer_line_shade});
        break;
      case DisplayMode::Wireframe:
        draw_lines(Primitives::Edges, Style{false, field, false, {}, layer_line_shade});
        break;
      case DisplayMode::HiddenLine:
        draw_faces(Style{false, false, true, kBackground, 1.0f});
        draw_lines(Primitives::Edges, Style{false, field, false, {}, layer_line_shade});
        break;
      case DisplayMode::Shaded:
        draw_faces(Style{true, field, false, {}, 1.0f});
        draw_lines(Primitives::Features, Style{false, false, true, kInk, 1.0f});
        break;
      case DisplayMode::ShadedEdges:
        draw_faces(Style{true, field, false, {}, 1.0f});
        draw_lines(Primitives::Edges, Style{false, false, true, kInk, 1.0f});
        break;
    }
    // Line elements in every mode but points (there, their nodes are drawn like all others): in
    // the layer colour as it is (not darkened like mesh lines: a bar is the element itself), or
    // in the contour colours.
    if (f.mode != DisplayMode::Points) draw_bars(f, Style{false, field, false, {}, 1.0f});
    draw_lines(Primitives::Outline, Style{false, false, true, kOutline, 1.0f});
    draw_ip_points(f);
  }

  // Shapes, then text blended over them; then the scene labels whose anchors the depth shows.
  void draw_overlay(const FrameView& f, const std::vector<float>* depth) {
    draw_triangles(f, f.overlay.triangles);
    text->draw(f.overlay.glyphs, f.overlay.atlas, f.width, f.height);
    if (!depth) return;
    const PlacedLabels labels = place_labels(f, *depth);
    draw_triangles(f, labels.markers);
    text->draw(labels.glyphs, f.overlay.atlas, f.width, f.height);
  }

  void draw_triangles(const FrameView& f, const std::vector<OverlayVertex>& v) {
    if (v.empty()) return;
    gl.Viewport(0, 0, f.width, f.height);
    gl.Disable(GL_DEPTH_TEST);
    gl.UseProgram(overlay_program.get());
    gl.Uniform2f(overlay_size, float(f.width), float(f.height));
    gl.BindVertexArray(overlay_array.get());
    gl.BindBuffer(GL_ARRAY_BUFFER, overlay_buffer.get());
    // Small and rebuilt per view (legend, title, markers): streamed every frame.
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(OverlayVertex)),
                  v.data(), GL_STREAM_DRAW);
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
  impl_->init();
}

GlRenderer::~GlRenderer() = default;

void GlRenderer::set_geometry(const FrameGeometry& geometry) { impl_->geometry->upload(geometry); }

void GlRenderer::draw_view(const FrameView& view) {
  Impl& r = *impl_;
  // The caller's framebuffer (0 for OSMesa, the widget's for Qt) receives the picture.
  GLint bound = 0;
  r.gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  const auto target = static_cast<GLuint>(bound);
  // Multisampling, or scene labels (which need the depth of the drawn picture), draw the scene
  // off screen first; otherwise it goes straight into the caller's framebuffer.
  const bool labels = !view.overlay.labels.empty();
  const bool offscreen = view.samples > 1 || labels;
  if (offscreen) {
    r.targets->prepare(view.width, view.height, view.samples);
    r.targets->bind_scene();
  }
  r.gl.Disable(GL_BLEND);
  r.gl.Viewport(0, 0, view.width, view.height);
  r.gl.ClearColor(kBackground.r, kBackground.g, kBackground.b, 1.0f);
  r.gl.ClearDepth(1.0);
  r.gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  r.gl.Enable(GL_PROGRAM_POINT_SIZE);
  if (offscreen && r.targets->samples() > 1)
    r.gl.Enable(GL_MULTISAMPLE);
  else
    r.gl.Disable(GL_MULTISAMPLE);
  r.draw_scene(view);
  r.gl.Disable(GL_MULTISAMPLE);
  std::vector<float> depth;
  if (offscreen) {
    r.targets->resolve();
    if (labels) depth = r.targets->read_depth(view.overlay.model, view.height);
    r.targets->copy_to(target);
  }
  r.draw_overlay(view, labels ? &depth : nullptr);
  r.gl.BindVertexArray(0);
}

void GlRenderer::draw(const Frame& frame) {
  set_geometry(frame.geometry);
  draw_view(frame);
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
