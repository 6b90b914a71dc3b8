#include "styk/render/annotations.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "face_shape.hpp"

namespace styk::render {
namespace {

using P3 = std::array<double, 3>;

P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 cross(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Where a node is drawn: deformed as `request` asks, relative to the skin's centre (the geometry's
// origin).
class Place {
 public:
  Place(const SkinModel& skin, const GeometryRequest& request)
      : model_(skin.model()),
        origin_(skin.centre()),
        u_(request.displacement),
        scale_(request.displacement ? request.scale : 0.0) {}
  P3 operator()(int node) const {
    const Vec3& x = model_.coords[node];
    P3 p{x[0] - origin_[0], x[1] - origin_[1], x[2] - origin_[2]};
    if (scale_ != 0.0)
      for (int k = 0; k < 3; ++k) p[k] += scale_ * (*u_)[node][k];
    return p;
  }

 private:
  const Model& model_;
  Vec3 origin_;
  const std::vector<Vec3>* u_;
  double scale_;
};

std::array<float, 3> to_float(const P3& p) { return {float(p[0]), float(p[1]), float(p[2])}; }

bool drawn(const GeometryRequest& request, const SkinModel& skin, const SkinFace& face) {
  if (!request.field || !request.hide_undefined_faces) return true;
  return face_carries(skin, *request.field, face);
}

// The centre of a drawn face (on its curved shape) and its outward normal.
std::pair<P3, P3> face_centre(const SkinModel& skin, const SkinFace& face, const Place& place) {
  const FaceShape& shape = skin.shapes().get(skin.formulations()[face.element], face.face);
  const int* conn = skin.model().element_nodes(face.element);
  const FacePatch& patch = shape.curved;
  const int n = patch.segments;
  P3 centre{}, ds{}, dt{};
  if (n % 2 == 0) {
    const int p = (n / 2) * (n + 1) + n / 2;
    const std::size_t count = patch.nodes.size();
    for (std::size_t a = 0; a < count; ++a) {
      const P3 x = place(conn[patch.nodes[a]]);
      for (int k = 0; k < 3; ++k) {
        centre[k] += patch.N[p * count + a] * x[k];
        ds[k] += patch.dNds[p * count + a] * x[k];
        dt[k] += patch.dNdt[p * count + a] * x[k];
      }
    }
  } else {  // a bilinear face: the mean of its corners, the corners' normal
    const P3 c0 = place(conn[shape.corners[0]]), c1 = place(conn[shape.corners[1]]),
             c2 = place(conn[shape.corners[2]]), c3 = place(conn[shape.corners[3]]);
    for (int k = 0; k < 3; ++k) centre[k] = 0.25 * (c0[k] + c1[k] + c2[k] + c3[k]);
    ds = sub(c2, c0), dt = sub(c3, c1);
  }
  P3 normal = cross(ds, dt);
  // Outward: away from the element's centre.
  const Element& element = skin.model().elements[face.element];
  P3 middle{};
  for (int k = 0; k < element.node_count; ++k) {
    const P3 x = place(conn[k]);
    for (int c = 0; c < 3; ++c) middle[c] += x[c] / element.node_count;
  }
  if (dot(normal, sub(centre, middle)) < 0) normal = {-normal[0], -normal[1], -normal[2]};
  const double length = std::sqrt(dot(normal, normal));
  if (length > 0)
    for (double& c : normal) c /= length;
  return {centre, normal};
}

bool listed(const std::vector<int>& only, int index) {
  return only.empty() || std::binary_search(only.begin(), only.end(), index);
}

}  // namespace

Rgb node_label_color() { return kInk; }
Rgb element_label_color() { return {0.6f, 0.0f, 0.05f}; }

std::vector<SceneLabel> scene_labels(const SkinModel& skin, const GeometryRequest& request,
                                     const Camera& camera, const LabelRequest& labels) {
  std::vector<SceneLabel> out;
  const Model& model = skin.model();
  const Place place(skin, request);
  const P3 eye{camera.toward_eye[0], camera.toward_eye[1], camera.toward_eye[2]};
  std::vector<char> node_seen(model.coords.size(), 0);
  std::map<int, std::pair<double, P3>> element_anchor;  // element -> facing, anchor
  for (const SkinModel::LayerSkin& layer : skin.layers()) {
    for (const SkinFace& face : layer.faces) {
      if (skin.face_def(face.element, face.face).nodes.empty() || !drawn(request, skin, face))
        continue;
      const int* conn = model.element_nodes(face.element);
      for (int a : skin.face_def(face.element, face.face).nodes) node_seen[conn[a]] = 1;
      if (!labels.elements || !listed(labels.only_elements, face.element)) continue;
      const auto [centre, normal] = face_centre(skin, face, place);
      const double facing = dot(normal, eye);
      if (facing <= 0) continue;
      auto it = element_anchor.find(face.element);
      if (it == element_anchor.end() || facing > it->second.first)
        element_anchor[face.element] = {facing, centre};
    }
    for (int e : layer.lines) {
      const int* conn = model.element_nodes(e);
      const int count = model.elements[e].node_count;
      for (int k = 0; k < count; ++k) node_seen[conn[k]] = 1;
      if (!labels.elements || !listed(labels.only_elements, e)) continue;
      const P3 a = place(conn[0]), b = place(conn[1]);
      element_anchor[e] = {1.0, {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])}};
    }
  }
  for (const auto& [element, anchor] : element_anchor)
    out.push_back(SceneLabel{to_float(anchor.second), std::to_string(model.elements[element].id),
                             element_label_color(), false});
  if (labels.nodes)
    for (std::size_t n = 0; n < node_seen.size(); ++n)
      if (node_seen[n] && listed(labels.only_nodes, int(n)))
        out.push_back(SceneLabel{to_float(place(int(n))), std::to_string(model.node_ids[n]),
                                 node_label_color(), true});
  return out;
}

void add_integration_points(const SkinModel& skin, const PointField& field,
                            const ColorScale& colors, const GeometryRequest& request,
                            FrameGeometry& geometry) {
  const Model& model = skin.model();
  const Place place(skin, request);
  std::map<const TElement*, std::vector<Vec3>> rules;
  std::vector<Vec3> nodes;
  for (const SkinModel::LayerSkin& layer : skin.layers())
    for (int e : layer.elements) {
      const TElement* formulation = skin.formulations()[e];
      auto it = rules.find(formulation);
      if (it == rules.end()) it = rules.emplace(formulation, point_coordinates(*formulation)).first;
      check_point_count(model, field, e, it->second.size());
      const int* conn = model.element_nodes(e);
      nodes.resize(static_cast<std::size_t>(model.elements[e].node_count));
      for (std::size_t k = 0; k < nodes.size(); ++k) {
        const P3 p = place(conn[k]);
        nodes[k] = {p[0], p[1], p[2]};
      }
      for (std::size_t q = 0; q < it->second.size(); ++q) {
        const Vec3 x = map_natural_point(*formulation, it->second[q], nodes);
        const float t = float(colors.normalized(field.values[field.offset[e] + q]));
        geometry.ip_points.push_back(
            Vertex{{float(x[0]), float(x[1]), float(x[2])}, {0, 0, 0}, {0, 0, 0}, t});
      }
    }
  for (const Vertex& v : geometry.ip_points)
    for (int k = 0; k < 3; ++k) {
      geometry.lower[k] = std::min(geometry.lower[k], v.position[k]);
      geometry.upper[k] = std::max(geometry.upper[k], v.position[k]);
    }
}

std::size_t visible_point_count(const SkinModel& skin, const PointField& field) {
  std::size_t count = 0;
  for (const SkinModel::LayerSkin& layer : skin.layers())
    for (int e : layer.elements) count += static_cast<std::size_t>(field.count(e));
  return count;
}

std::array<double, 2> point_field_range(const SkinModel& skin, const PointField& field) {
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for (const SkinModel::LayerSkin& layer : skin.layers())
    for (int e : layer.elements)
      for (int q = field.offset[e]; q < field.offset[e + 1]; ++q)
        lo = std::min(lo, field.values[q]), hi = std::max(hi, field.values[q]);
  if (lo > hi) return {0.0, 0.0};
  return {lo, hi};
}

}  // namespace styk::render
