#include "styk/elements/c3d20.hpp"

#include "styk/elements/hex_shapes.hpp"

namespace styk {

C3D20::C3D20() : nodes_(hex20_natural_nodes()), faces_(hex_faces(true)) {}

std::string C3D20::description() const {
  return "20-node quadratic (serendipity) hexahedron, full integration (3x3x3 Gauss)";
}

void C3D20::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                Eigen::Ref<Eigen::MatrixXd> dN) const {
  hex20_shape(xi, N, dN);
}

IntegrationRule C3D20::rule(RuleKind kind) const {
  return kind == RuleKind::Reduced ? gauss_rule(2, 2, 2) : gauss_rule(3, 3, 3);
}

}  // namespace styk
