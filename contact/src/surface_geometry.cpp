#include "surface_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "styk/core/face_param.hpp"

namespace styk::contact {
namespace {

// The two in-face axes of a cube face on axis `axis`, in increasing order.
std::array<int, 2> in_face_axes(int axis) {
  if (axis == 0) return {1, 2};
  if (axis == 1) return {0, 2};
  return {0, 1};
}

const FaceDef& face_of(const PlacedFace& f) { return f.element->faces()[f.face]; }

// A face of a plane or axisymmetric element is an edge in the x-y plane: one in-face coordinate
// p along it; q stands for z, the direction the edge is extruded (plane) or revolved (ring) in.
bool is_edge(const PlacedFace& f) {
  const ElementForm form = f.element->form();
  return form == ElementForm::Planar || form == ElementForm::Axisymmetric;
}

// dxi/dp and dxi/dq at (p, q), and the sign that turns their cross product outward.
void natural_tangents(const PlacedFace& f, double p, double q, Eigen::Vector3d& dp,
                      Eigen::Vector3d& dq, double& outward) {
  const FaceDef& face = face_of(f);
  if (is_edge(f)) {
    dp = Eigen::Vector3d::Unit(1 - face.axis);
    dq = Eigen::Vector3d::Unit(2);
    // e_p x e_z is +e_xi on a xi edge (e_eta x e_z) and -e_eta on an eta edge (e_xi x e_z); the
    // outward side is the sign of the edge's value.
    outward = (face.axis == 0 ? 1.0 : -1.0) * (face.value > 0.0 ? 1.0 : -1.0);
    return;
  }
  if (face.axis >= 0) {
    const std::array<int, 2> axes = in_face_axes(face.axis);
    dp = Eigen::Vector3d::Unit(axes[0]);
    dq = Eigen::Vector3d::Unit(axes[1]);
    // e_p x e_q is +axis for the zeta and xi faces, -eta for the eta faces; outward is -axis on
    // the -1 side.
    outward = (face.axis == 1 ? -1.0 : 1.0) * (face.value > 0.0 ? 1.0 : -1.0);
    return;
  }
  const FaceParam param(*f.element, face);
  param.tangents(p, q, dp, dq);
  outward = param.outward();
}

double beyond_face(const PlacedFace& f, double p, double q) {
  const FaceDef& face = face_of(f);
  if (is_edge(f)) return std::max(0.0, std::abs(p) - 1.0);
  if (face.axis >= 0) return std::max({0.0, std::abs(p) - 1.0, std::abs(q) - 1.0});
  return FaceParam(*f.element, face).outside(p, q);
}

}  // namespace

Vec3 face_point(const PlacedFace& f, double p, double q) {
  const FaceDef& face = face_of(f);
  if (is_edge(f)) {
    Vec3 xi{0.0, 0.0, 0.0};
    xi[face.axis] = face.value;
    xi[1 - face.axis] = p;
    return xi;
  }
  if (face.axis < 0) return FaceParam(*f.element, face).point(p, q);
  Vec3 xi{0.0, 0.0, 0.0};
  const std::array<int, 2> axes = in_face_axes(face.axis);
  xi[face.axis] = face.value;
  xi[axes[0]] = p;
  xi[axes[1]] = q;
  return xi;
}

std::array<double, 2> face_coordinates(const PlacedFace& f, const Vec3& xi) {
  const FaceDef& face = face_of(f);
  if (is_edge(f)) return {xi[1 - face.axis], 0.0};
  if (face.axis >= 0) {
    const std::array<int, 2> axes = in_face_axes(face.axis);
    return {xi[axes[0]], xi[axes[1]]};
  }
  // Newton on the (affine or bilinear) corner map; exact in one step for a triangle.
  const FaceParam param(*f.element, face);
  std::array<double, 2> pq = param.centre();
  const Eigen::Vector3d target(xi[0], xi[1], xi[2]);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Vec3 at = param.point(pq[0], pq[1]);
    Eigen::Vector3d dp, dq;
    param.tangents(pq[0], pq[1], dp, dq);
    Eigen::Matrix<double, 3, 2> T;
    T << dp, dq;
    const Eigen::Vector2d step =
        (T.transpose() * T)
            .ldlt()
            .solve(T.transpose() * (target - Eigen::Vector3d(at[0], at[1], at[2])));
    pq[0] += step[0];
    pq[1] += step[1];
    if (step.lpNorm<Eigen::Infinity>() < 1e-14) break;
  }
  return pq;
}

Eigen::VectorXd shape_values(const TElement& element, const Vec3& xi) {
  const int n = element.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  element.der(xi, N, dN);
  return N;
}

void face_map(const PlacedFace& f, double p, double q, Eigen::Vector3d& x, Eigen::Vector3d& xp,
              Eigen::Vector3d& xq) {
  const int n = f.element->node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  f.element->der(face_point(f, p, q), N, dN);
  Eigen::Vector3d dp, dq;
  double outward = 1.0;
  natural_tangents(f, p, q, dp, dq, outward);
  x = f.geometry.X.transpose() * N;
  xp = f.geometry.X.transpose() * (dN * dp);
  // An edge's second direction is z itself (the element has no extent along it).
  xq =
      is_edge(f) ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d(f.geometry.X.transpose() * (dN * dq));
}

Eigen::Vector3d outward_normal(const PlacedFace& f, double p, double q) {
  Eigen::Vector3d x, xp, xq, dp, dq;
  face_map(f, p, q, x, xp, xq);
  double outward = 1.0;
  natural_tangents(f, p, q, dp, dq, outward);
  Eigen::Vector3d n = outward * xp.cross(xq);
  const double length = n.norm();
  const double scale = xp.norm() * xq.norm();
  if (!(length > 1e-12 * scale)) return Eigen::Vector3d::Zero();
  return n / length;
}

Projection project_on_face(const PlacedFace& f, const Eigen::Vector3d& point) {
  Projection out;
  const FaceDef& face = face_of(f);
  if (face.axis < 0) {
    const std::array<double, 2> centre = FaceParam(*f.element, face).centre();
    out.p = centre[0];
    out.q = centre[1];
  }
  Eigen::Vector3d x, xp, xq;
  for (int iteration = 0; iteration < 30; ++iteration) {
    face_map(f, out.p, out.q, x, xp, xq);
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
  face_map(f, out.p, out.q, out.x, xp, xq);
  out.normal = outward_normal(f, out.p, out.q);
  out.beyond = beyond_face(f, out.p, out.q);
  return out;
}

}  // namespace styk::contact
