// Shared set-up of the element tests: reference and randomly distorted geometries, a unit
// material, and small numeric helpers. Deterministic: every random geometry comes from a seed.
#pragma once

#include <cmath>
#include <random>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "styk/core/element.hpp"

namespace styk::test {

// The reference cube [-1, 1]^3 itself (J = I at every point).
inline ElementGeometry reference_geometry(const TElement& element, Id id = 1) {
  ElementGeometry g;
  const auto& nodes = element.natural_nodes();
  g.X.resize(element.node_count(), 3);
  for (int i = 0; i < element.node_count(); ++i)
    for (int j = 0; j < 3; ++j) g.X(i, j) = nodes[i][j];
  g.id = id;
  g.where = SourceLoc{"test.inp", 7};
  return g;
}

// The reference cube with every node coordinate moved by a uniform random amount in
// [-amplitude, amplitude] (elements-ref/README.md section 7 uses nodes moved by up to 0.15).
inline ElementGeometry distorted_geometry(const TElement& element, unsigned seed,
                                          double amplitude = 0.15) {
  ElementGeometry g = reference_geometry(element);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-amplitude, amplitude);
  for (int i = 0; i < g.X.rows(); ++i)
    for (int j = 0; j < 3; ++j) g.X(i, j) += shift(rng);
  return g;
}

// E = 1, nu = 0.3: the material of the eigenvalue table in elements-ref/README.md section 7.
inline Material unit_material() {
  Material m;
  m.name = "UNIT";
  m.young = 1.0;
  m.poisson = 0.3;
  m.where = SourceLoc{"test.inp", 3};
  return m;
}

// Number of zero eigenvalues of a symmetric K, relative tolerance 1e-9 of the largest
// (elements-ref section 7).
inline int zero_eigenvalue_count(const Eigen::MatrixXd& K) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd lambda = solver.eigenvalues();
  const double largest = lambda.cwiseAbs().maxCoeff();
  int zeros = 0;
  for (Eigen::Index i = 0; i < lambda.size(); ++i)
    if (std::abs(lambda(i)) < 1e-9 * largest) ++zeros;
  return zeros;
}

// Nodal values (3n) of the linear field u = c + G x on the element's nodes.
inline Eigen::VectorXd linear_field(const ElementGeometry& g, const Eigen::Matrix3d& G,
                                    const Eigen::Vector3d& c) {
  Eigen::VectorXd u(3 * g.X.rows());
  for (Eigen::Index i = 0; i < g.X.rows(); ++i)
    u.segment<3>(3 * i) = c + G * g.X.row(i).transpose();
  return u;
}

}  // namespace styk::test
