#include "styk/core/tensor_ops.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/Eigenvalues>

namespace styk {

double mises(const Tensor6& s) {
  const double d12 = s[0] - s[1];
  const double d23 = s[1] - s[2];
  const double d31 = s[2] - s[0];
  const double shear = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
  return std::sqrt(0.5 * (d12 * d12 + d23 * d23 + d31 * d31) + 3.0 * shear);
}

std::array<double, 3> principal_values(const Tensor6& s) {
  Eigen::Matrix3d t;
  t << s[0], s[3], s[4],  //
      s[3], s[1], s[5],   //
      s[4], s[5], s[2];
  // The iterative solver (not computeDirect): accurate also for nearly repeated eigenvalues.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(t, Eigen::EigenvaluesOnly);
  std::array<double, 3> values = {solver.eigenvalues()(0), solver.eigenvalues()(1),
                                  solver.eigenvalues()(2)};
  std::sort(values.begin(), values.end(), std::greater<double>());
  return values;
}

}  // namespace styk
