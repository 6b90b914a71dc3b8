#include "styk/elements/wedges.hpp"

#include "styk/elements/wedge_shapes.hpp"

namespace styk {

C3D6::C3D6() : nodes_(wedge6_natural_nodes()), faces_(wedge_faces(false)) {}

std::string C3D6::description() const { return "6-node linear wedge (triangular prism), 2 points"; }

void C3D6::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
               Eigen::Ref<Eigen::MatrixXd> dN) const {
  wedge6_shape(xi, N, dN);
}

IntegrationRule C3D6::rule(RuleKind kind) const {
  return kind == RuleKind::Reduced ? wedge_rule(1, 1) : wedge_rule(1, 2);
}

C3D15::C3D15() : nodes_(wedge15_natural_nodes()), faces_(wedge_faces(true)) {}

std::string C3D15::description() const {
  return "15-node quadratic wedge (triangular prism), full integration (9 points)";
}

void C3D15::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                Eigen::Ref<Eigen::MatrixXd> dN) const {
  wedge15_shape(xi, N, dN);
}

IntegrationRule C3D15::rule(RuleKind kind) const {
  return kind == RuleKind::Reduced ? wedge_rule(3, 2) : wedge_rule(3, 3);
}

}  // namespace styk
