// Mechanics of the shell elements (shell.hpp): stiffness, pressure and body loads, the fibre
// stresses and the section forces, from the lamina strains of shell_kinematics.hpp.
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "shell_kinematics.hpp"
#include "styk/elements/quad_shapes.hpp"
#include "styk/elements/shell.hpp"

namespace styk {
namespace {

using shell_detail::LaminaPoint;
using shell_detail::ShellSetup;

void check_displacements(const Shell& shell, const ElementGeometry& g,
                         const Eigen::Ref<const Eigen::VectorXd>& u) {
  if (u.size() != 6 * shell.node_count())
    throw std::invalid_argument(shell_detail::label(shell, g) + ": displacement vector has " +
                                std::to_string(u.size()) + " entries, expected " +
                                std::to_string(6 * shell.node_count()));
}

void refuse_eigenstrains(const Shell& shell, const ElementGeometry& g,
                         const ElementMaterial& material, const Eigen::MatrixXd* initial_stress) {
  if (initial_stress != nullptr)
    throw InputError(g.where, shell_detail::label(shell, g) +
                                  ": *INITIAL CONDITIONS, TYPE=STRESS is not supported on shells");
  if (material.has_thermal_strain())
    throw InputError(g.where, shell_detail::label(shell, g) +
                                  ": temperature changes are not supported on shells");
}

// The drilling penalty alpha G t (theta . e3 - omega)^2 over the surface, full in-plane rule.
void add_drilling(const Shell& shell, const ElementGeometry& g, const ShellSetup& s,
                  Eigen::MatrixXd& K) {
  const IntegrationRule surface = quad_gauss_rule(shell.node_count() == 4 ? 2 : 3);
  const double k = shell_detail::kDrillingFactor * s.shear * s.thickness;
  Eigen::RowVectorXd row;
  double area = 0.0;
  for (int p = 0; p < surface.size(); ++p) {
    shell_detail::drilling_row(shell, g, s, surface.points[p][0], surface.points[p][1], row, area);
    K.noalias() += (k * area * surface.weights[p]) * row.transpose() * row;
  }
}

// Puts the symmetric tensor m (3x3) as row `row` in the order 11, 22, 33, 12, 13, 23.
void put_tensor(const Eigen::Matrix3d& m, Eigen::MatrixXd& rows, Eigen::Index row) {
  rows.row(row) << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2);
}

// Lamina stress (s11, s22, s12, s13, s23) as a 3x3 tensor in the lamina axes.
Eigen::Matrix3d lamina_tensor(const Eigen::Matrix<double, 5, 1>& v, double v33) {
  Eigen::Matrix3d m;
  m << v(0), v(2), v(3), v(2), v(1), v(4), v(3), v(4), v33;
  return m;
}

}  // namespace

void Shell::stiffness(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                      Eigen::MatrixXd& K, const ElementOptions&) const {
  const ShellSetup s = shell_detail::shell_setup(*this, g, material.material());
  const IntegrationRule surface = quad_gauss_rule(surface_order(kind));
  std::vector<double> zeta, wz;
  shell_detail::simpson(s.section_points, zeta, wz);
  K.setZero(6 * node_count(), 6 * node_count());
  LaminaPoint lp;
  int point = 0;
  for (int p = 0; p < surface.size(); ++p)
    for (std::size_t z = 0; z < zeta.size(); ++z) {
      shell_detail::lamina_point(*this, g, s, {surface.points[p][0], surface.points[p][1], zeta[z]},
                                 ++point, lp);
      K.noalias() += lp.B.transpose() * ((surface.weights[p] * wz[z] * lp.detJ) * s.D) * lp.B;
    }
  add_drilling(*this, g, s, K);
  K = 0.5 * (K + K.transpose()).eval();
}

void Shell::eigenstrain_load(const ElementGeometry& g, const ElementMaterial& material, RuleKind,
                             Eigen::VectorXd& f, const ElementOptions&,
                             const Eigen::MatrixXd* initial_stress) const {
  refuse_eigenstrains(*this, g, material, initial_stress);
  f.setZero(6 * node_count());
}

void Shell::pressure_load(const ElementGeometry& g, int face, double p, Eigen::VectorXd& f) const {
  if (face != 0)
    throw InputError(g.where, shell_detail::label(*this, g) +
                                  " takes the pressure label P (or P1), not P" +
                                  std::to_string(face + 1));
  const int n = node_count();
  const IntegrationRule surface = quad_gauss_rule(3);
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  f.setZero(6 * n);
  for (int k = 0; k < surface.size(); ++k) {
    der(surface.points[k], N, dN);
    // Reference surface (the nodes): dA = (g1 x g2) dxi deta; a positive P pushes along it, as
    // CalculiX applies P, P1 and P2 on its shells (measured with ccx 2.20).
    const Eigen::Vector3d g1 = g.X.transpose() * dN.col(0), g2 = g.X.transpose() * dN.col(1);
    const Eigen::Vector3d dA = g1.cross(g2);
    for (int a = 0; a < n; ++a) f.segment<3>(6 * a) += (p * surface.weights[k] * N(a)) * dA;
  }
}

void Shell::body_load(const ElementGeometry& g, double density, RuleKind,
                      const BodyAcceleration& acceleration, Eigen::VectorXd& f) const {
  if (g.section == nullptr || !g.section->shell || !g.section->thickness)
    throw InputError(g.where, shell_detail::label(*this, g) + " has no *SHELL SECTION");
  const double mass = density * *g.section->thickness;  // per unit area
  const int n = node_count();
  const IntegrationRule surface = quad_gauss_rule(3);
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  f.setZero(6 * n);
  for (int k = 0; k < surface.size(); ++k) {
    der(surface.points[k], N, dN);
    const Eigen::Vector3d g1 = g.X.transpose() * dN.col(0), g2 = g.X.transpose() * dN.col(1);
    const double area = g1.cross(g2).norm();
    const Eigen::Vector3d x = g.X.transpose() * N;
    const Vec3 a = acceleration.at({x(0), x(1), x(2)});
    const Eigen::Vector3d q(a[0], a[1], a[2]);
    for (int b = 0; b < n; ++b)
      f.segment<3>(6 * b) += (mass * area * surface.weights[k] * N(b)) * q;
  }
}

void Shell::strains_stresses(const ElementGeometry& g, const ElementMaterial& material,
                             RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                             Eigen::MatrixXd& strain, Eigen::MatrixXd& stress,
                             const ElementOptions&, const Eigen::MatrixXd* initial_stress) const {
  refuse_eigenstrains(*this, g, material, initial_stress);
  check_displacements(*this, g, u);
  const ShellSetup s = shell_detail::shell_setup(*this, g, material.material());
  const IntegrationRule r = rule(kind);
  strain.resize(r.size(), 6);
  stress.resize(r.size(), 6);
  LaminaPoint lp;
  for (int k = 0; k < r.size(); ++k) {
    shell_detail::lamina_point(*this, g, s, r.points[k], k + 1, lp);
    Eigen::Matrix<double, 5, 1> e = lp.B * u;
    const Eigen::Matrix<double, 5, 1> sigma = s.D * e;
    // Tensor strains; eps33 from sigma33 = 0.
    const double e33 = -s.poisson / (1.0 - s.poisson) * (e(0) + e(1));
    e.tail<3>() *= 0.5;
    put_tensor(lp.R * lamina_tensor(sigma, 0.0) * lp.R.transpose(), stress, k);
    put_tensor(lp.R * lamina_tensor(e, e33) * lp.R.transpose(), strain, k);
  }
}

void Shell::section_resultants(const ElementGeometry& g, const ElementMaterial& material,
                               RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                               Eigen::MatrixXd& forces, Eigen::MatrixXd& moments) const {
  refuse_eigenstrains(*this, g, material, nullptr);
  check_displacements(*this, g, u);
  const ShellSetup s = shell_detail::shell_setup(*this, g, material.material());
  const IntegrationRule surface = quad_gauss_rule(surface_order(kind));
  std::vector<double> zeta, wz;
  shell_detail::simpson(s.section_points, zeta, wz);
  forces.setZero(surface.size(), 5);  // N11, N22, N12, Q13, Q23
  moments.setZero(surface.size(), 3);
  LaminaPoint lp;
  for (int p = 0; p < surface.size(); ++p)
    for (std::size_t z = 0; z < zeta.size(); ++z) {
      shell_detail::lamina_point(*this, g, s, {surface.points[p][0], surface.points[p][1], zeta[z]},
                                 p + 1, lp);
      const Eigen::Matrix<double, 5, 1> sigma = s.D * (lp.B * u);
      const double dz = 0.5 * s.thickness * wz[z];
      const double from_mid = 0.5 * s.thickness * zeta[z];
      forces.row(p) += dz * sigma.transpose();
      moments.row(p) += (dz * from_mid) * sigma.head<3>().transpose();
    }
}

}  // namespace styk
