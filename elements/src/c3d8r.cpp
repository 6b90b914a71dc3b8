#include "styk/elements/c3d8r.hpp"

#include <array>

#include <Eigen/Dense>

namespace styk {

C3D8R::C3D8R(double hourglass_stiffness) : kappa_(hourglass_stiffness) {}

std::string C3D8R::description() const {
  return kappa_ > 0.0 ? "8-node linear hexahedron, 1-point rule + Flanagan-Belytschko stiffness "
                        "hourglass control"
                      : "C3D8R WITHOUT hourglass control (demonstrates hourglassing; do not use)";
}

IntegrationRule C3D8R::rule(RuleKind) const { return gauss_rule(1, 1, 1); }

double C3D8R::uniform_gradient(const ElementGeometry& g, Eigen::Ref<Eigen::MatrixXd> b_bar) const {
  const IntegrationRule exact = gauss_rule(2, 2, 2);
  Eigen::VectorXd N(8);
  Eigen::MatrixXd dN(8, 3), dNdx(8, 3);
  b_bar.setZero();
  double volume = 0.0;
  for (int k = 0; k < exact.size(); ++k) {
    der(exact.points[k], N, dN);
    const double dv = exact.weights[k] * jacobian(g, dN, dNdx, k + 1);
    b_bar += dv * dNdx;
    volume += dv;
  }
  b_bar /= volume;
  return volume;
}

double C3D8R::point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>&,
                            const Eigen::Ref<const Eigen::MatrixXd>&,
                            Eigen::Ref<Eigen::MatrixXd> dNdx, int) const {
  return uniform_gradient(g, dNdx) / 8.0;  // the 1-point rule's weight is 8
}

void C3D8R::add_stabilisation(const ElementGeometry& g, const Matrix6d& D, const ElementOptions&,
                              Eigen::MatrixXd& K) const {
  if (kappa_ <= 0.0) return;
  Eigen::MatrixXd dNdx(8, 3);
  const double volume = uniform_gradient(g, dNdx);
  // b : b with b = V B_bar, the FB "B-vectors"; divided by V it scales like modulus * length.
  const double bb = volume * volume * dNdx.squaredNorm();
  const double stiffness_modulus = (D(0, 0) + D(1, 1) + D(2, 2)) / 3.0;  // lambda + 2 mu
  const double c = kappa_ * stiffness_modulus * bb / (8.0 * volume);

  const auto& nodes = natural_nodes();
  Eigen::Matrix<double, 8, 3> X = g.X;
  Eigen::Matrix<double, 8, 8> hourglass = Eigen::Matrix<double, 8, 8>::Zero();
  for (int alpha = 0; alpha < 4; ++alpha) {
    Eigen::Matrix<double, 8, 1> h;
    for (int a = 0; a < 8; ++a) {
      const Vec3& s = nodes[a];
      const std::array<double, 4> base = {s[0] * s[1], s[1] * s[2], s[2] * s[0],
                                          s[0] * s[1] * s[2]};
      h(a) = base[alpha];
    }
    // Remove the part of h that an affine field would see: gamma^T (c + X g) = 0 for all c, g.
    const Eigen::Matrix<double, 8, 1> gamma = h - dNdx * (X.transpose() * h);
    hourglass.noalias() += gamma * gamma.transpose();
  }
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b)
      for (int d = 0; d < 3; ++d) K(3 * a + d, 3 * b + d) += c * hourglass(a, b);
}

}  // namespace styk
