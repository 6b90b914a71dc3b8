#include "styk/elements/plane_quads.hpp"

#include "styk/elements/quad_shapes.hpp"

namespace styk {

PlaneQuad4::PlaneQuad4(PlaneKind kind)
    : PlaneElement(kind), nodes_(quad4_natural_nodes()), edges_(quad_edges(false)) {}

std::string PlaneQuad4::description() const {
  return "4-node bilinear quadrilateral, " + kind_words() + ", full integration (2x2 Gauss)";
}

void PlaneQuad4::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                     Eigen::Ref<Eigen::MatrixXd> dN) const {
  quad4_shape(xi, N, dN);
}

IntegrationRule PlaneQuad4::rule(RuleKind kind) const {
  return quad_gauss_rule(kind == RuleKind::Reduced ? 1 : 2);
}

PlaneQuad8::PlaneQuad8(PlaneKind kind, bool reduced)
    : PlaneElement(kind),
      reduced_(reduced),
      nodes_(quad8_natural_nodes()),
      edges_(quad_edges(true)) {}

std::string PlaneQuad8::description() const {
  return "8-node quadratic quadrilateral, " + kind_words() +
         (reduced_ ? ", reduced integration (2x2 Gauss)" : ", full integration (3x3 Gauss)");
}

void PlaneQuad8::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                     Eigen::Ref<Eigen::MatrixXd> dN) const {
  quad8_shape(xi, N, dN);
}

IntegrationRule PlaneQuad8::rule(RuleKind kind) const {
  return quad_gauss_rule(reduced_ || kind == RuleKind::Reduced ? 2 : 3);
}

}  // namespace styk
