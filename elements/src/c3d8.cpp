#include "styk/elements/c3d8.hpp"

#include "styk/elements/hex_shapes.hpp"

namespace styk {

C3D8::C3D8() : nodes_(hex8_natural_nodes()), faces_(hex_faces(false)) {}

std::string C3D8::description() const {
  return "8-node linear hexahedron, full integration (2x2x2 Gauss)";
}

void C3D8::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
               Eigen::Ref<Eigen::MatrixXd> dN) const {
  hex8_shape(xi, N, dN);
}

IntegrationRule C3D8::rule(RuleKind kind) const {
  return kind == RuleKind::Reduced ? gauss_rule(1, 1, 1) : gauss_rule(2, 2, 2);
}

}  // namespace styk
