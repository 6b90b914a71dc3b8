#include "session/highlight.hpp"

#include <algorithm>
#include <cmath>

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

void outline_face(const Scene& scene, int element, int face, double width,
                  std::vector<render::OverlayVertex>& out) {
  const std::vector<int> corners = face_corner_nodes(scene, element, face);
  for (std::size_t i = 0; i < corners.size(); ++i)
    add_line(out, scene.screen_position(corners[i]),
             scene.screen_position(corners[(i + 1) % corners.size()]), width, kHighlight);
}

}  // namespace

std::vector<int> face_corner_nodes(const Scene& scene, int element, int face) {
  const render::SkinModel& skin = *scene.skin();
  const TElement& formulation = *skin.formulations()[element];
  const FaceDef& def = formulation.faces()[face];
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
  for (int n : selection.nodes()) {
    if (n < 0 || n >= model.node_count()) continue;
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
      outline_face(scene, f.element, f.face - 1, width, triangles);
  }
  if (selection.elements().empty()) return;
  // An element is outlined along its faces on the skin (the only ones that can be seen).
  const std::vector<int>& elements = selection.elements();
  for (const render::SkinModel::LayerSkin& layer : scene.skin()->layers())
    for (const render::SkinFace& face : layer.faces)
      if (std::binary_search(elements.begin(), elements.end(), face.element))
        outline_face(scene, face.element, face.face, width, triangles);
}

}  // namespace styk::gui
