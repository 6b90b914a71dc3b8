#include "styk/elements/axisymmetric.hpp"

#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "edge_quadrature.hpp"
#include "styk/elements/quad_shapes.hpp"

namespace styk {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;
// Hourglass stiffness scale of CAX4R (the value C3D8R uses).
constexpr double kHourglassKappa = 0.005;

std::string label(const ElementGeometry& g, const TElement& e) {
  return "element " + std::to_string(g.id) + " (" + e.name() + ")";
}

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

// r = x at a point with shape-function values N.
double radius(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& N) {
  return N.dot(g.X.col(0));
}

}  // namespace

double AxisymmetricElement::point_measure(const ElementGeometry& g,
                                          const Eigen::Ref<const Eigen::VectorXd>& N,
                                          const Eigen::Ref<const Eigen::MatrixXd>& dN,
                                          Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const {
  Eigen::Matrix2d J;
  J.noalias() = dN.leftCols<2>().transpose() * g.X.leftCols<2>();  // J(i, j) = dx_j / dxi_i
  const double det = J.determinant();
  const double scale = J.row(0).norm() * J.row(1).norm();
  if (!(det > 1e-12 * scale))
    throw InputError(g.where, label(g, *this) + ": Jacobian determinant " + format_number(det) +
                                  " at integration point " + std::to_string(point) +
                                  " is not positive: the element is inverted, degenerate or its "
                                  "nodes run clockwise in the r-z (x-y) plane");
  const double r = radius(g, N);
  if (!(r > 0.0))
    throw InputError(g.where, label(g, *this) + ": integration point " + std::to_string(point) +
                                  " lies at r = x = " + format_number(r) +
                                  "; an axisymmetric element must lie at x >= 0 (x is the "
                                  "radius, y the axis)");
  dNdx.leftCols<2>().noalias() = dN.leftCols<2>() * J.inverse().transpose();
  dNdx.col(2).setZero();
  return kTwoPi * r * det;
}

void AxisymmetricElement::strain_operator(const ElementGeometry& g,
                                          const Eigen::Ref<const Eigen::VectorXd>& N,
                                          const Eigen::Ref<const Eigen::MatrixXd>& dNdx,
                                          Eigen::Ref<Eigen::MatrixXd> B) const {
  const double r = radius(g, N);
  B.setZero();
  for (Eigen::Index a = 0; a < dNdx.rows(); ++a) {
    const double dr = dNdx(a, 0), dz = dNdx(a, 1);
    const Eigen::Index c = 3 * a;
    B(0, c) = dr;        // e_rr
    B(1, c + 1) = dz;    // e_zz
    B(2, c) = N(a) / r;  // e_hoop = u_r / r
    B(3, c) = dz;        // g_rz
    B(3, c + 1) = dr;
  }
}

void AxisymmetricElement::face_quadrature(const ElementGeometry& g, const FaceDef& face,
                                          std::vector<Vec3>& points,
                                          std::vector<Eigen::Vector3d>& weighted_normals) const {
  // As for plane elements, times the ring's circumference 2 pi r in place of the thickness.
  elements_detail::edge_quadrature(
      *this, g, face, [&](const Eigen::VectorXd& N) { return kTwoPi * radius(g, N); }, points,
      weighted_normals);
}

CAX4::CAX4(bool reduced)
    : reduced_(reduced), nodes_(quad4_natural_nodes()), edges_(quad_edges(false)) {}

std::string CAX4::description() const {
  return reduced_ ? "4-node axisymmetric ring, reduced integration (1 point) + hourglass control"
                  : "4-node axisymmetric ring, full integration (2x2 Gauss)";
}

void CAX4::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
               Eigen::Ref<Eigen::MatrixXd> dN) const {
  quad4_shape(xi, N, dN);
}

IntegrationRule CAX4::rule(RuleKind kind) const {
  return quad_gauss_rule(reduced_ || kind == RuleKind::Reduced ? 1 : 2);
}

void CAX4::add_stabilisation(const ElementGeometry& g, const Matrix6d& D, const ElementOptions&,
                             Eigen::MatrixXd& K) const {
  if (!reduced_) return;
  // The centre's Cartesian derivatives and the section area (det J at the centre x 4).
  Eigen::VectorXd N(4);
  Eigen::MatrixXd dN(4, 3);
  quad4_shape({0.0, 0.0, 0.0}, N, dN);
  Eigen::Matrix2d J;
  J.noalias() = dN.leftCols<2>().transpose() * g.X.leftCols<2>();
  const Eigen::Matrix<double, 4, 2> dNdx = dN.leftCols<2>() * J.inverse().transpose();
  const double area = 4.0 * J.determinant();
  const double r0 = N.dot(g.X.col(0));
  // gamma = h - dN/dx(0) (X^T h), h = (1, -1, 1, -1) at the corners: orthogonal to every affine
  // nodal field, so the constant-strain patch (u_r = a r included) is untouched.
  Eigen::Vector4d h(1.0, -1.0, 1.0, -1.0);
  const Eigen::Matrix<double, 4, 2> X = g.X.leftCols<2>();
  const Eigen::Vector4d gamma = h - dNdx * (X.transpose() * h);
  const double modulus = (D(0, 0) + D(1, 1) + D(2, 2)) / 3.0;  // lambda + 2 mu
  const double c = kHourglassKappa * modulus * area * dNdx.squaredNorm() * kTwoPi * r0 / 4.0;
  const Eigen::Matrix4d hourglass = c * gamma * gamma.transpose();
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int d = 0; d < 2; ++d) K(3 * a + d, 3 * b + d) += hourglass(a, b);
}

CAX8::CAX8(bool reduced)
    : reduced_(reduced), nodes_(quad8_natural_nodes()), edges_(quad_edges(true)) {}

std::string CAX8::description() const {
  return reduced_ ? "8-node axisymmetric ring, reduced integration (2x2 Gauss)"
                  : "8-node axisymmetric ring, full integration (3x3 Gauss)";
}

void CAX8::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
               Eigen::Ref<Eigen::MatrixXd> dN) const {
  quad8_shape(xi, N, dN);
}

IntegrationRule CAX8::rule(RuleKind kind) const {
  return quad_gauss_rule(reduced_ || kind == RuleKind::Reduced ? 2 : 3);
}

}  // namespace styk
