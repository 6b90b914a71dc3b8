#include "styk/elements/c3d8i.hpp"

#include <Eigen/Dense>

namespace styk {

std::string C3D8I::description() const {
  return "8-node linear hexahedron with 9 incompatible (bending) modes, 2x2x2 Gauss";
}

void C3D8I::incompatible_bee(const ElementGeometry& g, const Vec3& xi, double detJ,
                             Eigen::Ref<Eigen::MatrixXd> G) const {
  Eigen::Matrix<double, 8, 1> N;
  Eigen::Matrix<double, 8, 3> dN;
  der(Vec3{0.0, 0.0, 0.0}, N, dN);
  const Eigen::Matrix3d J0 = dN.transpose() * g.X;  // J0(i, j) = dx_j / dxi_i at the centre
  // Natural derivatives of the bubbles P_k = 1 - xi_k^2 (one row per bubble), mapped with J0 and
  // scaled by det J0 / det J: the Taylor correction that makes the integral of G dV vanish.
  Eigen::Matrix3d dP = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 3; ++k) dP(k, k) = -2.0 * xi[k];
  const Eigen::Matrix3d dPdx = (J0.determinant() / detJ) * dP * J0.inverse().transpose();
  // The three bubbles act on ux, uy, uz like three extra nodes: G is their BEE, parameters
  // ordered (bubble 1: x y z, bubble 2: x y z, bubble 3: x y z).
  TElement::bee(dPdx, G);
}

}  // namespace styk
