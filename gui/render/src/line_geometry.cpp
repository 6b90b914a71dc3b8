#include "line_geometry.hpp"

#include <map>

namespace styk::render {
namespace {

// The scale position of one element node's value; -1 (no field) when the field has none there.
class LineColouring {
 public:
  LineColouring(const Model& model, const GeometryRequest& request)
      : model_(model), field_(request.field), colors_(request.colors) {}

  bool has_field() const { return field_ != nullptr; }
  bool discrete() const { return field_ && !field_->categories.empty(); }

  // Whether the field has a value at every node of element `e`.
  bool covers(int e) const {
    if (!field_ || field_->defined.empty()) return true;
    const int* conn = model_.element_nodes(e);
    for (int k = 0; k < model_.elements[e].node_count; ++k)
      if (!field_->defined[conn[k]]) return false;
    return true;
  }

  float t(int e, int local) const {
    const Element& element = model_.elements[e];
    double value = 0.0;
    switch (field_->location) {
      case FieldLocation::Node:
        value = field_->values[model_.element_nodes(e)[local]];
        break;
      case FieldLocation::ElementNode:
        value = field_->values[element.first_node + local];
        break;
      case FieldLocation::Element:
        value = field_->values[e];
        break;
    }
    return static_cast<float>(colors_->normalized(value));
  }

 private:
  const Model& model_;
  const ScalarField* field_;
  const ColorScale* colors_;
};

Vertex bar_vertex(const std::array<double, 3>& p, const Rgb& color, float t) {
  return Vertex{{float(p[0]), float(p[1]), float(p[2])}, {0, 0, 0}, {color.r, color.g, color.b}, t};
}

}  // namespace

void add_line_elements(const SkinModel& skin, const SkinModel::LayerSkin& layer,
                       const GeometryRequest& request, const Vec3& origin,
                       std::vector<Vertex>& bars) {
  if (layer.lines.empty()) return;
  const Model& model = skin.model();
  const double scale = request.displacement ? request.scale : 0.0;
  // The same arithmetic as the faces' placement, so bar ends and face corners coincide.
  const auto place = [&](int node) {
    const Vec3& x = model.coords[node];
    std::array<double, 3> p{x[0] - origin[0], x[1] - origin[1], x[2] - origin[2]};
    if (scale != 0.0) {
      const Vec3& d = (*request.displacement)[node];
      for (int k = 0; k < 3; ++k) p[k] = p[k] + scale * d[k];
    }
    return p;
  };
  const LineColouring colouring(model, request);
  std::map<const TElement*, std::vector<int>> orders;  // a handful of formulations
  for (int e : layer.lines) {
    const TElement* formulation = skin.formulations()[e];
    auto order = orders.find(formulation);
    if (order == orders.end())
      order = orders.emplace(formulation, line_node_order(*formulation)).first;
    const bool coloured = colouring.has_field() && colouring.covers(e);
    if (colouring.has_field() && !coloured && request.hide_undefined_faces) continue;
    const Rgb color = colouring.has_field() && !coloured ? neutral_face_color() : layer.color;
    const int* conn = model.element_nodes(e);
    const std::vector<int>& along = order->second;
    for (std::size_t k = 0; k + 1 < along.size(); ++k) {
      const int a = along[k], b = along[k + 1];
      const std::array<double, 3> pa = place(conn[a]), pb = place(conn[b]);
      const float ta = coloured ? colouring.t(e, a) : -1.0f;
      const float tb = coloured ? colouring.t(e, b) : -1.0f;
      if (coloured && colouring.discrete()) {
        // Each end's category over its half of the segment.
        const std::array<double, 3> mid{0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]),
                                        0.5 * (pa[2] + pb[2])};
        bars.push_back(bar_vertex(pa, color, ta));
        bars.push_back(bar_vertex(mid, color, ta));
        bars.push_back(bar_vertex(mid, color, tb));
        bars.push_back(bar_vertex(pb, color, tb));
      } else {
        bars.push_back(bar_vertex(pa, color, ta));
        bars.push_back(bar_vertex(pb, color, tb));
      }
    }
  }
}

}  // namespace styk::render
