#include "styk/elements/c3d27.hpp"

#include "styk/elements/hex_shapes.hpp"

namespace styk {

C3D27::C3D27() : nodes_(hex27_natural_nodes()), faces_(hex27_faces()) {}

std::string C3D27::description() const {
  return "27-node triquadratic (Lagrange) hexahedron, full integration (3x3x3 Gauss)";
}

void C3D27::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                Eigen::Ref<Eigen::MatrixXd> dN) const {
  hex27_shape(xi, N, dN);
}

IntegrationRule C3D27::rule(RuleKind kind) const {
  return kind == RuleKind::Reduced ? gauss_rule(2, 2, 2) : gauss_rule(3, 3, 3);
}

}  // namespace styk
