#include "styk/elements/t3d2.hpp"

#include <cstdio>

namespace styk {
namespace {

std::string label(const ElementGeometry& g) {
  return "element " + std::to_string(g.id) + " (T3D2)";
}

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

}  // namespace

T3D2::T3D2() : nodes_{{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}} {}

std::string T3D2::description() const {
  return "2-node linear truss (axial force only), 1 integration point, area from the section";
}

void T3D2::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
               Eigen::Ref<Eigen::MatrixXd> dN) const {
  N(0) = 0.5 * (1.0 - xi[0]);
  N(1) = 0.5 * (1.0 + xi[0]);
  dN.setZero();
  dN(0, 0) = -0.5;
  dN(1, 0) = 0.5;
}

IntegrationRule T3D2::rule(RuleKind) const {
  IntegrationRule rule;
  rule.label = "1-point Gauss";
  rule.points = {{0.0, 0.0, 0.0}};
  rule.weights = {2.0};
  return rule;
}

void T3D2::bee(const Eigen::Ref<const Eigen::MatrixXd>& dNdx, Eigen::Ref<Eigen::MatrixXd> B) const {
  B.setZero();
  for (Eigen::Index a = 0; a < dNdx.rows(); ++a) B.block<1, 3>(0, 3 * a) = dNdx.row(a);
}

void T3D2::dee(const MaterialPoint& material, Matrix6d& D) const {
  // Uniaxial along the bar: the modulus of an isotropic law. A direction-dependent law or
  // expansion would need the bar's axis in the material axes, which Styk does not model.
  if (!material.isotropic || !material.isotropic_expansion)
    throw InputError({},
                     "element type T3D2 takes an isotropic material only (*ELASTIC, "
                     "TYPE=ISO and *EXPANSION, TYPE=ISO)");
  D.setZero();
  D(0, 0) = material.young;  // uniaxial: no lateral stress, whatever nu
}

double T3D2::point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>&,
                           const Eigen::Ref<const Eigen::MatrixXd>& dN,
                           Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const {
  if (!(g.cross_section > 0.0))
    throw InputError(g.where, label(g) + ": cross-section area " + format_number(g.cross_section) +
                                  " must be positive (first data line of its *SOLID SECTION)");
  const Eigen::Vector3d tangent = g.X.transpose() * dN.col(0);  // dx/dxi = L/2 t
  const double length_scale = g.X.cwiseAbs().maxCoeff();
  const double J = tangent.norm();
  if (!(J > 1e-12 * length_scale))
    throw InputError(g.where, label(g) + ": zero length at integration point " +
                                  std::to_string(point) + " (its two nodes coincide)");
  const Eigen::Vector3d t = tangent / J;
  for (Eigen::Index a = 0; a < dN.rows(); ++a) dNdx.row(a) = (dN(a, 0) / J) * t.transpose();
  return J * g.cross_section;
}

}  // namespace styk
