#include "session/highlight.hpp"

#include <algorithm>
#include <cmath>

#include "session/picking.hpp"
#include "session/scene.hpp"
#include "styk/render/skin.hpp"

namespace styk::gui {
namespace {

void add_quad(std::vector<render::OverlayVertex>& out, const float (&x)[4], const float (&y)[4],
              const render::Rgb& c) {
  const int order[6] = {0, 1, 2, 0, 2, 3};
  for (int i : order) out.push_back({x[i], y[i], {c.r, c.g, c.b}});
}

void add_square(std::vector<render::OverlayVertex>& out, double cx, double cy, double half,
                const render::Rgb& c) {
  const float l = float(cx - half), r = float(cx + half), t = float(cy - half),
              b = float(cy + half);
  add_quad(out, {l, r, r, l}, {t, t, b, b}, c);
}

// A line of `width` pixels from a to b, as a quad.
void add_line(std::vector<render::OverlayVertex>& out, const std::array<double, 3>& a,
              const std::array<double, 3>& b, double width, const render::Rgb& c) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length = std::hypot(dx, dy);
  if (length < 1e-9) return;
  const double nx = -dy / length * width * 0.5, ny = dx / length * width * 0.5;
  add_quad(out, {float(a[0] + nx), float(b[0] + nx), float(b[0] - nx), float(a[0] - nx)},
           {float(a[1] + ny), float(b[1] + ny), float(b[1] - ny), float(a[1] - ny)}, c);
}

// The visible stretches of the edge a-b: sampled every pixel, each sample tested against the
// picker's face-id buffer, consecutive visible samples joined into one line.
void outline_edge(const Scene& scene, const Picker& picker, int a, int b, double width,
                  std::vector<render::OverlayVertex>& out) {
  const std::array<double, 3> pa = scene.screen_position(a), pb = scene.screen_position(b);
  const int samples = std::max(1, int(std::ceil(std::hypot(pb[0] - pa[0], pb[1] - pa[1]))));
  const auto at = [&](int i) {
    const double t = double(i) / samples;
    return std::array<double, 3>{pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]), 0.0};
  };
  int start = -1;  // first sample of the visible stretch being collected
  for (int i = 0; i <= samples; ++i) {
    const std::array<double, 3> p = at(i);
    const bool visible = picker.edge_point_visible(p[0], p[1], a, b);
    if (visible && start < 0) start = i;
    if ((!visible || i == samples) && start >= 0) {
      const int end = visible ? i : i - 1;
      if (end > start) add_line(out, at(start), at(end), width, kHighlight);
      start = -1;
    }
  }
}

void outline_face(const Scene& scene, const Picker& picker, int element, int face, double width,
                  std::vector<render::OverlayVertex>& out) {
  const std::vector<int> corners = face_corner_nodes(scene, element, face);
  for (std::size_t i = 0; i < corners.size(); ++i)
    outline_edge(scene, picker, corners[i], corners[(i + 1) % corners.size()], width, out);
}

// The nodes of line element `element` (model indices) in their order along the line.
std::vector<int> bar_nodes(const Scene& scene, int element) {
  const int* nodes = scene.model()->element_nodes(element);
  std::vector<int> result;
  for (int k : render::line_node_order(*scene.skin()->formulations()[element]))
    result.push_back(nodes[k]);
  return result;
}

// The screen bounding box of everything `selection` marks: its nodes, and the corners of its faces
// and of its elements' skin faces.
render::PixelRect selection_region(const Scene& scene, const Selection& selection) {
  const Model& model = *scene.model();
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  const auto add = [&](int node) {
    const std::array<double, 3> p = scene.screen_position(node);
    x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
  };
  for (int n : selection.nodes())
    if (n >= 0 && n < model.node_count()) add(n);
  for (const SurfaceFace& f : selection.faces()) {
    if (f.element < 0 || f.element >= model.element_count()) continue;
    const int count = int(scene.skin()->formulations()[f.element]->faces().size());
    if (f.face >= 1 && f.face <= count)
      for (int n : face_corner_nodes(scene, f.element, f.face - 1)) add(n);
  }
  const std::vector<int>& elements = selection.elements();
  if (!elements.empty())
    for (const render::SkinModel::LayerSkin& layer : scene.skin()->layers()) {
      for (const render::SkinFace& face : layer.faces)
        if (std::binary_search(elements.begin(), elements.end(), face.element))
          for (int n : face_corner_nodes(scene, face.element, face.face)) add(n);
      for (int e : layer.lines)
        if (std::binary_search(elements.begin(), elements.end(), e))
          for (int n : bar_nodes(scene, e)) add(n);
    }
  if (x0 > x1) return {};  // nothing to mark: an empty region rasterises almost nothing
  return {int(std::floor(x0)), int(std::floor(y0)), int(std::ceil(x1 - std::floor(x0))) + 1,
          int(std::ceil(y1 - std::floor(y0))) + 1};
}

}  // namespace

std::vector<int> face_corner_nodes(const Scene& scene, int element, int face) {
  const render::SkinModel& skin = *scene.skin();
  const TElement& formulation = *skin.formulations()[element];
  const FaceDef& def = skin.face_def(element, face);
  const int corners = render::face_corner_count(formulation, def);
  const int* nodes = scene.model()->element_nodes(element);
  std::vector<int> result;
  for (int k = 0; k < corners; ++k) result.push_back(nodes[def.nodes[k]]);
  return result;
}

void append_highlight(const Scene& scene, const Selection& selection,
                      std::vector<render::OverlayVertex>& triangles) {
  if (!scene.skin() || !scene.model()) return;
  const Model& model = *scene.model();
  const render::PixelRect& area = scene.last_frame().overlay.model;
  const double unit = std::max(2.0, double(scene.last_frame().point_size) * 0.5);
  const double width = std::max(2.0, unit);
  // Only what is seen from the camera is marked: the same face-id buffer as picking, built only
  // around the selection (every lookup below stays within the reach of a selected point or edge).
  const Picker picker(scene, selection_region(scene, selection));
  for (int n : selection.nodes()) {
    if (n < 0 || n >= model.node_count() || !picker.node_visible(n)) continue;
    const std::array<double, 3> p = scene.screen_position(n);
    if (p[0] < area.x || p[0] > area.x + area.width || p[1] < area.y || p[1] > area.y + area.height)
      continue;
    add_square(triangles, p[0], p[1], 2.5 * unit, render::kInk);
    add_square(triangles, p[0], p[1], 1.5 * unit, kHighlight);
  }
  for (const SurfaceFace& f : selection.faces()) {
    if (f.element < 0 || f.element >= model.element_count()) continue;
    const int count = int(scene.skin()->formulations()[f.element]->faces().size());
    if (f.face >= 1 && f.face <= count)
      outline_face(scene, picker, f.element, f.face - 1, width, triangles);
  }
  if (selection.elements().empty()) return;
  // An element is outlined along its faces on the skin (the only ones that can be seen).
  const std::vector<int>& elements = selection.elements();
  for (const render::SkinModel::LayerSkin& layer : scene.skin()->layers()) {
    for (const render::SkinFace& face : layer.faces)
      if (std::binary_search(elements.begin(), elements.end(), face.element))
        outline_face(scene, picker, face.element, face.face, width, triangles);
    // A bar (line element) is traced along its seen stretches.
    for (int e : layer.lines)
      if (std::binary_search(elements.begin(), elements.end(), e)) {
        const std::vector<int> nodes = bar_nodes(scene, e);
        for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
          outline_edge(scene, picker, nodes[i], nodes[i + 1], width, triangles);
      }
  }
}

}  // namespace styk::gui
