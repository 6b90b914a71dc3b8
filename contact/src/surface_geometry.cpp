#include "surface_geometry.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

namespace styk::contact {
namespace {

// The two in-face axes of a face on axis `axis`, in increasing order.
std::array<int, 2> in_face_axes(int axis) {
  if (axis == 0) return {1, 2};
  if (axis == 1) return {0, 2};
  return {0, 1};
}

}  // namespace

Vec3 face_point(const FaceDef& face, double p, double q) {
  Vec3 xi{0.0, 0.0, 0.0};
  const std::array<int, 2> axes = in_face_axes(face.axis);
  xi[face.axis] = face.value;
  xi[axes[0]] = p;
  xi[axes[1]] = q;
  return xi;
}

Eigen::VectorXd shape_values(const TElement& element, const Vec3& xi) {
  const int n = element.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  element.der(xi, N, dN);
  return N;
}

void face_map(const PlacedFace& f, const Vec3& xi, Eigen::Vector3d& x, Eigen::Vector3d& xp,
              Eigen::Vector3d& xq) {
  const int n = f.element->node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  f.element->der(xi, N, dN);
  const FaceDef& face = f.element->faces()[f.face];
  const std::array<int, 2> axes = in_face_axes(face.axis);
  x = f.geometry.X.transpose() * N;
  xp = f.geometry.X.transpose() * dN.col(axes[0]);
  xq = f.geometry.X.transpose() * dN.col(axes[1]);
}

Eigen::Vector3d outward_normal(const PlacedFace& f, const Vec3& xi) {
  Eigen::Vector3d x, xp, xq;
  face_map(f, xi, x, xp, xq);
  // x,p x x,q follows the natural axis completing (p, q) to a right-handed triple only for the
  // zeta faces; for xi faces (axes eta, zeta) it is +xi, for eta faces (xi, zeta) it is -eta.
  const FaceDef& face = f.element->faces()[f.face];
  const double handedness = face.axis == 1 ? -1.0 : 1.0;
  Eigen::Vector3d n = handedness * (face.value > 0.0 ? 1.0 : -1.0) * xp.cross(xq);
  const double length = n.norm();
  const double scale = xp.norm() * xq.norm();
  if (!(length > 1e-12 * scale)) return Eigen::Vector3d::Zero();
  return n / length;
}

double Projection::outside() const { return std::max({0.0, std::abs(p) - 1.0, std::abs(q) - 1.0}); }

Projection project_on_face(const PlacedFace& f, const Eigen::Vector3d& point) {
  const FaceDef& face = f.element->faces()[f.face];
  Projection out;
  Eigen::Vector3d x, xp, xq;
  for (int iteration = 0; iteration < 30; ++iteration) {
    face_map(f, face_point(face, out.p, out.q), x, xp, xq);
    // Gauss-Newton on |x(p, q) - point|^2 (the curvature term is dropped: it vanishes at a
    // zero-distance solution and only slows convergence otherwise).
    Eigen::Matrix2d A;
    A << xp.dot(xp), xp.dot(xq), xq.dot(xp), xq.dot(xq);
    const Eigen::Vector2d b(xp.dot(point - x), xq.dot(point - x));
    const Eigen::Vector2d step = A.ldlt().solve(b);
    if (!step.allFinite()) break;
    // Keep the iterate near the face: far outside the parameterisation means nothing.
    out.p = std::clamp(out.p + step[0], -3.0, 3.0);
    out.q = std::clamp(out.q + step[1], -3.0, 3.0);
    if (step.lpNorm<Eigen::Infinity>() < 1e-13) {
      out.converged = true;
      break;
    }
  }
  const Vec3 xi = face_point(face, out.p, out.q);
  face_map(f, xi, out.x, xp, xq);
  out.normal = outward_normal(f, xi);
  return out;
}

}  // namespace styk::contact
