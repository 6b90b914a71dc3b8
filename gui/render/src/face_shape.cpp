#include "face_shape.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "styk/render/skin.hpp"

namespace styk::render {
namespace {

Vec3 lerp_bilinear(const std::array<Vec3, 4>& c, double s, double t) {
  Vec3 x{};
  for (int k = 0; k < 3; ++k)
    x[k] = (1 - s) * (1 - t) * c[0][k] + s * (1 - t) * c[1][k] + s * t * c[2][k] +
           (1 - s) * t * c[3][k];
  return x;
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  Vec3 ab{}, ap{};
  double ab2 = 0.0, along = 0.0;
  for (int k = 0; k < 3; ++k)
    ab[k] = b[k] - a[k], ap[k] = p[k] - a[k], ab2 += ab[k] * ab[k], along += ab[k] * ap[k];
  const double u = ab2 > 0 ? std::clamp(along / ab2, 0.0, 1.0) : 0.0;
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k) d2 += (ap[k] - u * ab[k]) * (ap[k] - u * ab[k]);
  return std::sqrt(d2);
}

FacePatch make_patch(const TElement& element, const std::array<Vec3, 4>& c, int segments) {
  const int n = element.node_count();
  const int grid = segments + 1;
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  std::vector<double> all_N, all_ds, all_dt;  // [point * n + a]
  for (int j = 0; j < grid; ++j) {
    for (int i = 0; i < grid; ++i) {
      const double s = static_cast<double>(i) / segments, t = static_cast<double>(j) / segments;
      const Vec3 xi = lerp_bilinear(c, s, t);
      Vec3 dxi_ds{}, dxi_dt{};
      for (int k = 0; k < 3; ++k) {
        dxi_ds[k] = (1 - t) * (c[1][k] - c[0][k]) + t * (c[2][k] - c[3][k]);
        dxi_dt[k] = (1 - s) * (c[3][k] - c[0][k]) + s * (c[2][k] - c[1][k]);
      }
      element.der(xi, N, dN);
      for (int a = 0; a < n; ++a) {
        all_N.push_back(N(a));
        all_ds.push_back(dN(a, 0) * dxi_ds[0] + dN(a, 1) * dxi_ds[1] + dN(a, 2) * dxi_ds[2]);
        all_dt.push_back(dN(a, 0) * dxi_dt[0] + dN(a, 1) * dxi_dt[1] + dN(a, 2) * dxi_dt[2]);
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
  const std::array<Vec3, 4> c = {xi[shape.corners[0]], xi[shape.corners[1]], xi[shape.corners[2]],
                                 xi[shape.corners[3]]};

  // Degree: nodes on the busiest edge (corners included) minus one; interior nodes make it >= 2.
  int degree = 1;
  std::vector<int> on_edges(face.nodes.size(), 0);
  for (int e = 0; e < shape.corner_count; ++e) {
    const Vec3& a = c[e];
    const Vec3& b = c[(e + 1) % shape.corner_count];
    int count = 0;
    for (std::size_t k = 0; k < face.nodes.size(); ++k)
      if (distance_to_segment(xi[face.nodes[k]], a, b) < 1e-9) ++count, on_edges[k] = 1;
    degree = std::max(degree, count - 1);
  }
  for (std::size_t k = static_cast<std::size_t>(shape.corner_count); k < face.nodes.size(); ++k)
    if (!on_edges[k]) degree = std::max(degree, 2);
  shape.curved_segments =
      face.nodes.size() > static_cast<std::size_t>(shape.corner_count) ? 2 * degree : 1;

  // (s, t) of the other face nodes: exact for the axis-parallel square faces of hexahedra; a node
  // off that square simply never passes the bilinear test, so its face is drawn curved.
  const auto dot = [](const Vec3& u, const Vec3& v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  const Vec3 es = {c[1][0] - c[0][0], c[1][1] - c[0][1], c[1][2] - c[0][2]};
  const Vec3 et = {c[3][0] - c[0][0], c[3][1] - c[0][1], c[3][2] - c[0][2]};
  for (std::size_t k = static_cast<std::size_t>(shape.corner_count); k < face.nodes.size(); ++k) {
    const Vec3& p = xi[face.nodes[k]];
    const Vec3 d = {p[0] - c[0][0], p[1] - c[0][1], p[2] - c[0][2]};
    const double ss = dot(es, es) > 0 ? dot(d, es) / dot(es, es) : 0.0;
    const double tt = dot(et, et) > 0 ? dot(d, et) / dot(et, et) : 0.0;
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
    const std::array<Vec3, 4> c = {xi[shape.corners[0]], xi[shape.corners[1]], xi[shape.corners[2]],
                                   xi[shape.corners[3]]};
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
