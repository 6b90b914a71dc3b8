// mises() and principal_values() (core/include/styk/core/tensor_ops.hpp) against hand-computed
// tensors.
#include <cmath>

#include <gtest/gtest.h>

#include "styk/core/tensor_ops.hpp"

namespace styk {
namespace {

TEST(TensorOps, MisesOfUniaxialStressIsItsMagnitude) {
  EXPECT_DOUBLE_EQ(mises({-250.0, 0, 0, 0, 0, 0}), 250.0);
  EXPECT_DOUBLE_EQ(mises({0, 0, 7.0, 0, 0, 0}), 7.0);
}

TEST(TensorOps, MisesOfPureShearIsSqrt3Tau) {
  EXPECT_NEAR(mises({0, 0, 0, 10.0, 0, 0}), std::sqrt(3.0) * 10.0, 1e-12);
  EXPECT_NEAR(mises({0, 0, 0, 0, 0, -10.0}), std::sqrt(3.0) * 10.0, 1e-12);
}

TEST(TensorOps, MisesIgnoresHydrostaticPressure) {
  EXPECT_NEAR(mises({-300.0, -300.0, -300.0, 0, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(mises({1000.0, 900.0, 900.0, 0, 0, 0}), 100.0, 1e-9);
}

// SPEC §3.1.8: sigma = 2000 on the diagonal, tau = 400 off it -> Mises 1200.
TEST(TensorOps, PatchTestStateGivesMises1200) {
  EXPECT_NEAR(mises({2000, 2000, 2000, 400, 400, 400}), 1200.0, 1e-9);
}

TEST(TensorOps, PrincipalValuesOfDiagonalTensorAreSortedDescending) {
  const auto p = principal_values({-5.0, 3.0, 1.0, 0, 0, 0});
  EXPECT_DOUBLE_EQ(p[0], 3.0);
  EXPECT_DOUBLE_EQ(p[1], 1.0);
  EXPECT_DOUBLE_EQ(p[2], -5.0);
}

// [[2000,400,400],[400,2000,400],[400,400,2000]] = 1600 I + 400 * ones: eigenvalues 2800, 1600,
// 1600; and a plane shear state with eigenvalues s11/2+s22/2 +- sqrt(((s11-s22)/2)^2 + s12^2).
TEST(TensorOps, PrincipalValuesOfShearedTensors) {
  const auto p = principal_values({2000, 2000, 2000, 400, 400, 400});
  EXPECT_NEAR(p[0], 2800.0, 1e-9);
  EXPECT_NEAR(p[1], 1600.0, 1e-9);
  EXPECT_NEAR(p[2], 1600.0, 1e-9);
  const auto q = principal_values({30.0, -10.0, 5.0, 15.0, 0, 0});
  const double radius = std::sqrt(20.0 * 20.0 + 15.0 * 15.0);  // 25
  EXPECT_NEAR(q[0], 10.0 + radius, 1e-12);
  EXPECT_NEAR(q[1], 5.0, 1e-12);
  EXPECT_NEAR(q[2], 10.0 - radius, 1e-12);
}

TEST(TensorOps, MisesFromPrincipalValuesAgrees) {
  const Tensor6 s = {120.0, -40.0, 15.0, 33.0, -21.0, 8.0};
  const auto p = principal_values(s);
  const double from_principal =
      std::sqrt(0.5 * ((p[0] - p[1]) * (p[0] - p[1]) + (p[1] - p[2]) * (p[1] - p[2]) +
                       (p[2] - p[0]) * (p[2] - p[0])));
  EXPECT_NEAR(mises(s), from_principal, 1e-10);
  EXPECT_NEAR(p[0] + p[1] + p[2], 120.0 - 40.0 + 15.0, 1e-10);
}

}  // namespace
}  // namespace styk
