#include "face_shape.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "styk/render/skin.hpp"

namespace styk::render {
namespace {

using V3 = Eigen::Vector3d;

V3 point(const Vec3& x) { return V3(x[0], x[1], x[2]); }

V3 lerp_bilinear(const std::array<V3, 4>& c, double s, double t) {
  return (1 - s) * (1 - t) * c[0] + s * (1 - t) * c[1] + s * t * c[2] + (1 - s) * t * c[3];
}

double distance_to_segment(const V3& p, const V3& a, const V3& b) {
  const V3 ab = b - a, ap = p - a;
  const double ab2 = ab.squaredNorm();
  const double u = ab2 > 0 ? std::clamp(ab.dot(ap) / ab2, 0.0, 1.0) : 0.0;
  return (ap - u * ab).norm();
}

FacePatch make_patch(const TElement& element, const std::array<V3, 4>& c, int segments) {
  const int n = element.node_count();
  const int grid = segments + 1;
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  std::vector<double> all_N, all_ds, all_dt;  // [point * n + a]
  for (int j = 0; j < grid; ++j) {
    for (int i = 0; i < grid; ++i) {
      const double s = static_cast<double>(i) / segments, t = static_cast<double>(j) / segments;
      const V3 xi = lerp_bilinear(c, s, t);
      const V3 dxi_ds = (1 - t) * (c[1] - c[0]) + t * (c[2] - c[3]);
      const V3 dxi_dt = (1 - s) * (c[3] - c[0]) + s * (c[2] - c[1]);
      element.der({xi[0], xi[1], xi[2]}, N, dN);
      const Eigen::VectorXd along_s = dN * dxi_ds, along_t = dN * dxi_dt;
      for (int a = 0; a < n; ++a) {
        all_N.push_back(N(a));
        all_ds.push_back(along_s(a));
        all_dt.push_back(along_t(a));
      }
    }
  }
  FacePatch patch;
  patch.segments = segments;
  const int points = grid * grid;
  for (int a = 0; a < n; ++a) {
    double largest = 0.0;
    for (int p = 0; p < points; ++p)
      largest = std::max({largest, std::abs(all_N[p * n + a]), std::abs(all_ds[p * n + a]),
                          std::abs(all_dt[p * n + a])});
    if (largest > 1e-12) patch.nodes.push_back(a);
  }
  for (int p = 0; p < points; ++p)
    for (int a : patch.nodes) {
      patch.N.push_back(all_N[p * n + a]);
      patch.dNds.push_back(all_ds[p * n + a]);
      patch.dNdt.push_back(all_dt[p * n + a]);
    }
  return patch;
}

FaceShape make_shape(const TElement& element, const FaceDef& face) {
  FaceShape shape;
  shape.corner_count = face_corner_count(element, face);
  for (int k = 0; k < 4; ++k) shape.corners[k] = face.nodes[std::min(k, shape.corner_count - 1)];
  const std::vector<Vec3>& xi = element.natural_nodes();
  const std::array<V3, 4> c = {point(xi[shape.corners[0]]), point(xi[shape.corners[1]]),
                               point(xi[shape.corners[2]]), point(xi[shape.corners[3]])};

  // Degree: nodes on the busiest edge (corners included) minus one; interior nodes make it >= 2.
  int degree = 1;
  std::vector<int> on_edges(face.nodes.size(), 0);
  for (int e = 0; e < shape.corner_count; ++e) {
    const V3& a = c[e];
    const V3& b = c[(e + 1) % shape.corner_count];
    int count = 0;
    for (std::size_t k = 0; k < face.nodes.size(); ++k)
      if (distance_to_segment(point(xi[face.nodes[k]]), a, b) < 1e-9) ++count, on_edges[k] = 1;
    degree = std::max(degree, count - 1);
  }
  for (std::size_t k = static_cast<std::size_t>(shape.corner_count); k < face.nodes.size(); ++k)
    if (!on_edges[k]) degree = std::max(degree, 2);
  shape.curved_segments =
      face.nodes.size() > static_cast<std::size_t>(shape.corner_count) ? 2 * degree : 1;

  // (s, t) of the other face nodes: exact for the axis-parallel square faces of hexahedra; a node
  // off that square simply never passes the bilinear test, so its face is drawn curved.
  const V3 es = c[1] - c[0], et = c[3] - c[0];
  for (std::size_t k = static_cast<std::size_t>(shape.corner_count); k < face.nodes.size(); ++k) {
    const V3 d = point(xi[face.nodes[k]]) - c[0];
    const double ss = es.squaredNorm() > 0 ? d.dot(es) / es.squaredNorm() : 0.0;
    const double tt = et.squaredNorm() > 0 ? d.dot(et) / et.squaredNorm() : 0.0;
    shape.extra_nodes.push_back(face.nodes[k]);
    shape.extra_st.push_back({ss, tt});
  }
  shape.flat = make_patch(element, c, 1);
  shape.curved =
      shape.curved_segments > 1 ? make_patch(element, c, shape.curved_segments) : shape.flat;
  shape.split = shape.curved_segments >= 2 ? shape.curved : make_patch(element, c, 2);
  return shape;
}

}  // namespace

const FacePatch& FaceShapes::refined(const TElement* element, int face, int level) const {
  const auto key = std::make_tuple(element, face, level);
  auto it = refined_.find(key);
  if (it == refined_.end()) {
    const FaceShape& shape = get(element, face);
    const std::vector<Vec3>& xi = element->natural_nodes();
    const std::array<V3, 4> c = {point(xi[shape.corners[0]]), point(xi[shape.corners[1]]),
                                 point(xi[shape.corners[2]]), point(xi[shape.corners[3]])};
    it = refined_.emplace(key, make_patch(*element, c, shape.curved_segments << level)).first;
  }
  return it->second;
}

FaceShapes::FaceShapes(const std::vector<const TElement*>& formulations) {
  for (const TElement* element : formulations) {
    if (!element || shapes_.count(element)) continue;
    std::vector<FaceShape> faces;
    // Placeholders (a planar element's edges, see drawn_faces) keep the face indices.
    for (const FaceDef& face : drawn_faces(*element))
      faces.push_back(face.nodes.empty() ? FaceShape{} : make_shape(*element, face));
    shapes_.emplace(element, std::move(faces));
  }
}

}  // namespace styk::render
