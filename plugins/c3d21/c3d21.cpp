#include "c3d21.hpp"

#include "styk/elements/hex_shapes.hpp"

namespace styk::plugins {

namespace {

constexpr int kBottomCentre = 20;  // node 21, 0-based

std::vector<Vec3> c3d21_nodes() {
  std::vector<Vec3> nodes = hex20_natural_nodes();
  nodes.push_back(Vec3{0.0, 0.0, -1.0});
  return nodes;
}

std::vector<FaceDef> c3d21_faces() {
  std::vector<FaceDef> faces = hex_faces(true);
  faces[0].nodes.push_back(kBottomCentre);  // S1: 4 corners, 4 mid-edges, centre
  return faces;
}

}  // namespace

C3D21::C3D21() : nodes_(c3d21_nodes()), faces_(c3d21_faces()) {}

std::string C3D21::description() const {
  return "21-node contact hexahedron (C3D20 + S1 centre: 9-node Lagrange contact face S1), "
         "3x3x3 Gauss";
}

// Compact form (elements-ref section 3, verified identical to the corrected printed set):
// B = 1/2 (1 - xi^2)(1 - eta^2) zeta (zeta - 1), the bottom-face bubble (= 1 at node 21, 0 on
// S2-S6); N1..N4 = C3D20 + B/4, N9..N12 = C3D20 - B/2, all others = C3D20, N21 = B.
void C3D21::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                Eigen::Ref<Eigen::MatrixXd> dN) const {
  hex20_shape(xi, N.head<20>(), dN.topRows<20>());
  const double x = xi[0], y = xi[1], z = xi[2];
  const double bx = 1.0 - x * x, by = 1.0 - y * y, bz = 0.5 * z * (z - 1.0);
  const double B = bx * by * bz;
  const Eigen::RowVector3d dB(-2.0 * x * by * bz, -2.0 * y * bx * bz, bx * by * (z - 0.5));
  N(kBottomCentre) = B;
  dN.row(kBottomCentre) = dB;
  for (int i = 0; i < 4; ++i) {  // bottom corners 1-4
    N(i) += 0.25 * B;
    dN.row(i) += 0.25 * dB;
  }
  for (int i = 8; i < 12; ++i) {  // bottom mid-edges 9-12
    N(i) -= 0.5 * B;
    dN.row(i) -= 0.5 * dB;
  }
}

IntegrationRule C3D21::rule(RuleKind kind) const {
  return kind == RuleKind::Reduced ? gauss_rule(2, 2, 2) : gauss_rule(3, 3, 3);
}

}  // namespace styk::plugins
