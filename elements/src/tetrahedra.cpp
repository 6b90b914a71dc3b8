#include "styk/elements/tetrahedra.hpp"

#include "styk/elements/tet_shapes.hpp"

namespace styk {

C3D4::C3D4() : nodes_(tet4_natural_nodes()), faces_(tet_faces(false)) {}

std::string C3D4::description() const {
  return "4-node linear tetrahedron, constant strain (1 point); stiff in bending";
}

void C3D4::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
               Eigen::Ref<Eigen::MatrixXd> dN) const {
  tet4_shape(xi, N, dN);
}

IntegrationRule C3D4::rule(RuleKind) const { return tet_rule_1(); }

C3D10::C3D10() : nodes_(tet10_natural_nodes()), faces_(tet_faces(true)) {}

std::string C3D10::description() const {
  return "10-node quadratic tetrahedron, full integration (4 points)";
}

void C3D10::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                Eigen::Ref<Eigen::MatrixXd> dN) const {
  tet10_shape(xi, N, dN);
}

IntegrationRule C3D10::rule(RuleKind kind) const {
  return kind == RuleKind::Reduced ? tet_rule_1() : tet_rule_4();
}

}  // namespace styk
