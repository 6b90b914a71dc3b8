// The STRI3 triangle (stri3.hpp): node layout, shape functions, rules and loads. The mechanics
// (stiffness, stresses, section forces) is in stri3_mechanics.cpp.
#include "styk/elements/stri3.hpp"

#include <Eigen/Dense>

#include "shell_kinematics.hpp"

namespace styk {
namespace {

// The triangle's 3-point rule (points inside, weights 1/6: exact to second order).
IntegrationRule triangle_rule() {
  IntegrationRule r;
  r.points = {
      {1.0 / 6.0, 1.0 / 6.0, 0.0}, {2.0 / 3.0, 1.0 / 6.0, 0.0}, {1.0 / 6.0, 2.0 / 3.0, 0.0}};
  r.weights = {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
  return r;
}

// (x2 - x1) x (x3 - x1): twice the area along the element normal.
Eigen::Vector3d area_normal(const ElementGeometry& g) {
  const Eigen::Vector3d a = (g.X.row(1) - g.X.row(0)).transpose();
  const Eigen::Vector3d b = (g.X.row(2) - g.X.row(0)).transpose();
  return a.cross(b);
}

}  // namespace

Stri3::Stri3() : nodes_{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}} {}

std::string Stri3::description() const {
  return "3-node flat thin (Kirchhoff) shell triangle: discrete-Kirchhoff (DKT) bending, "
         "constant-strain membrane, 3-point rule";
}

void Stri3::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                Eigen::Ref<Eigen::MatrixXd> dN) const {
  N << 1.0 - xi[0] - xi[1], xi[0], xi[1];
  dN.setZero();
  dN(0, 0) = dN(0, 1) = -1.0;
  dN(1, 0) = 1.0;
  dN(2, 1) = 1.0;
}

IntegrationRule Stri3::rule(RuleKind) const {
  return shell_detail::with_fibres(triangle_rule(),
                                   "3-point triangle rule x bottom, middle and top fibre");
}

double Stri3::point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>&,
                            const Eigen::Ref<const Eigen::MatrixXd>& dN,
                            Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const {
  return shell_detail::surface_point_measure(*this, g, dN, dNdx, point,
                                             "degenerate triangle (its corners are on one line)");
}

void Stri3::eigenstrain_load(const ElementGeometry& g, const ElementMaterial& material, RuleKind,
                             Eigen::VectorXd& f, const ElementOptions&,
                             const Eigen::MatrixXd* initial_stress) const {
  if (initial_stress != nullptr)
    throw InputError(g.where, shell_detail::label(*this, g) +
                                  ": *INITIAL CONDITIONS, TYPE=STRESS is not supported on shells");
  if (material.has_thermal_strain())
    throw InputError(g.where, shell_detail::label(*this, g) +
                                  ": temperature changes are not supported on shells");
  f.setZero(18);
}

void Stri3::pressure_load(const ElementGeometry& g, int face, double p, Eigen::VectorXd& f) const {
  if (face != 0)
    throw InputError(g.where, shell_detail::label(*this, g) +
                                  " takes the pressure label P (or P1), not P" +
                                  std::to_string(face + 1));
  const Eigen::Vector3d force = p * area_normal(g) / 2.0;  // p times the area along the normal
  f.setZero(18);
  for (int a = 0; a < 3; ++a) f.segment<3>(6 * a) = force / 3.0;
}

void Stri3::body_load(const ElementGeometry& g, double density, RuleKind,
                      const BodyAcceleration& acceleration, Eigen::VectorXd& f) const {
  if (g.section == nullptr || !g.section->shell || !g.section->thickness)
    throw InputError(g.where, shell_detail::label(*this, g) + " has no *SHELL SECTION");
  const double mass = density * *g.section->thickness * area_normal(g).norm();  // 2 x the mass
  const IntegrationRule surface = triangle_rule();
  Eigen::VectorXd N(3);
  Eigen::MatrixXd dN(3, 3);
  f.setZero(18);
  for (int k = 0; k < surface.size(); ++k) {
    der(surface.points[k], N, dN);
    const Eigen::Vector3d x = g.X.transpose() * N;
    const Vec3 a = acceleration.at({x(0), x(1), x(2)});
    const Eigen::Vector3d q(a[0], a[1], a[2]);
    for (int b = 0; b < 3; ++b) f.segment<3>(6 * b) += (mass * surface.weights[k] * N(b)) * q;
  }
}

}  // namespace styk
