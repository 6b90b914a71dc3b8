// Checks every element type must pass, shared by the tetrahedron, wedge and axisymmetric tests:
// the energy-gradient (finite-difference) check of the stiffness and the counting of zero
// eigenvalues on the displacements the type stiffens.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "styk/core/element.hpp"

namespace styk::test {

// Strain energy of displacement u from the element's own strain and stress recovery at its
// integration points: W = 1/2 sum_k w_k dV_k sigma_k . eps_k (engineering shear strains), plus
// 1/2 u . K_stab u of a stabilisation stiffness (hourglass control), which acts outside the
// points.
inline double strain_energy(const TElement& e, const ElementGeometry& g, const Material& m,
                            RuleKind kind, const Eigen::VectorXd& u) {
  Eigen::MatrixXd strain, stress;
  e.strains_stresses(g, m, kind, u, strain, stress);
  const IntegrationRule rule = e.rule(kind);
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
  double W = 0.0;
  for (int k = 0; k < rule.size(); ++k) {
    e.der(rule.points[k], N, dN);
    const double dv = rule.weights[k] * e.point_measure(g, N, dN, dNdx, k + 1);
    Eigen::Matrix<double, 6, 1> engineering = strain.row(k).transpose();
    engineering.tail<3>() *= 2.0;
    W += 0.5 * dv * stress.row(k).dot(engineering.transpose());
  }
  Matrix6d D;
  e.dee(material_point(m), D);
  Eigen::MatrixXd K_stab = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  e.add_stabilisation(g, D, {}, K_stab);
  return W + 0.5 * u.dot(K_stab * u);
}

// max_i |dW/du_i (central differences) - (K u)_i| / max_i |(K u)_i|: the stiffness against the
// element's own strains and stresses. W is quadratic, so central differences are exact up to
// round-off.
inline double stiffness_gradient_error(const TElement& e, const ElementGeometry& g,
                                       const Material& m, RuleKind kind, const Eigen::VectorXd& u) {
  Eigen::MatrixXd K;
  e.stiffness(g, m, kind, K);
  const Eigen::VectorXd Ku = K * u;
  const double h = 1e-3 * u.cwiseAbs().maxCoeff();
  double worst = 0.0;
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    Eigen::VectorXd plus = u, minus = u;
    plus[i] += h;
    minus[i] -= h;
    const double gradient =
        (strain_energy(e, g, m, kind, plus) - strain_energy(e, g, m, kind, minus)) / (2 * h);
    worst = std::max(worst, std::abs(gradient - Ku[i]));
  }
  return worst / Ku.cwiseAbs().maxCoeff();
}

// Zero eigenvalues (relative 1e-9 of the largest) of K restricted to the displacements the type
// stiffens (ux, uy for plane and axisymmetric elements).
inline int active_zero_eigenvalues(const TElement& e, const Eigen::MatrixXd& K) {
  const DofSet active = e.active_dofs();
  std::vector<int> dofs;
  for (int i = 0; i < K.rows(); ++i)
    if (active[i % 3]) dofs.push_back(i);
  Eigen::MatrixXd Kr(dofs.size(), dofs.size());
  for (std::size_t r = 0; r < dofs.size(); ++r)
    for (std::size_t c = 0; c < dofs.size(); ++c) Kr(r, c) = K(dofs[r], dofs[c]);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(Kr, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd lambda = solver.eigenvalues();
  const double largest = lambda.cwiseAbs().maxCoeff();
  int zeros = 0;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) zeros += std::abs(lambda(i)) < 1e-9 * largest;
  return zeros;
}

}  // namespace styk::test
