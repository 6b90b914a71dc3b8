// The local complementarity laws of styk_contact (friction_law.hpp): classification and the
// semi-smooth Newton rows, the slip rows checked against central finite differences of the slip
// function (STYLE practice 9: the contact tangent is what Newton's convergence rests on).
#include "styk/contact/friction_law.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "slip_rows_check.hpp"

namespace styk::contact {
namespace {

LocalPoint slipping_point() {
  LocalPoint p;
  p.lambda = {2.0, 0.7, -0.4};
  p.d = {0.31, 0.9, 0.25};
  p.d_ref = {0.0, 0.1, -0.2};
  p.gap0 = 0.3;
  p.c_n = 1.7;
  p.c_t = 2.3;
  p.live = {true, true, true};
  return p;
}

TEST(FrictionLaw, Classification) {
  LocalPoint p = slipping_point();
  EXPECT_EQ(classify(p), NodeStatus::Slip);
  p.tied = true;
  EXPECT_EQ(classify(p), NodeStatus::Stick);
  p.tied = false;
  p.d.tail<2>() = p.d_ref.tail<2>();  // no tangential motion, |lambda_t| < lambda_n
  EXPECT_EQ(classify(p), NodeStatus::Stick);
  p.lambda[0] = -1.0;
  p.d[0] = p.gap0 - 0.1;  // tension and an open gap
  EXPECT_EQ(classify(p), NodeStatus::Open);
  p.live = {true, false, false};  // frictionless: closed nodes slide freely
  p.lambda[0] = 1.0;
  EXPECT_EQ(classify(p), NodeStatus::Slip);
  p.tied = true;
  EXPECT_EQ(classify(p), NodeStatus::Stick);
}

// Q and D of the slip rows are the derivatives of F_t = lambda_t - b xi / |xi|; r is consistent
// with the Newton step C(x_k) + J (x - x_k) = 0 written as Q d + D lambda = r.
TEST(FrictionLaw, SlipTangentMatchesFiniteDifferences) {
  const LocalPoint p = slipping_point();
  ASSERT_EQ(classify(p), NodeStatus::Slip);
  const LocalRows rows = linearise(p, NodeStatus::Slip);
  test::expect_slip_rows_match_finite_differences(p, rows, 1e-6, 1e-7);
  const Eigen::Vector3d consistent = rows.Q * p.d + rows.D * p.lambda;
  const Eigen::Vector2d C = slip_function(p);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(rows.r[1 + i], consistent[1 + i] - C[i], 1e-12);
  // The normal row of a closed node is the equality d_n = gap0.
  EXPECT_EQ(rows.Q(0, 0), 1.0);
  EXPECT_EQ(rows.r[0], p.gap0);
}

TEST(FrictionLaw, ResidualVanishesExactlyOnTheLaw) {
  LocalPoint p = slipping_point();
  // A slipping solution: closed (d_n = gap0), lambda_t = lambda_n * direction of the slip.
  p.d[0] = p.gap0;
  const Eigen::Vector2d slip(0.3, -0.4);
  p.d.tail<2>() = p.d_ref.tail<2>() + slip;
  p.lambda.tail<2>() = p.lambda[0] * slip.normalized();
  EXPECT_LT(complementarity_residual(p).norm(), 1e-14);
  EXPECT_EQ(classify(p), NodeStatus::Slip);
  p.lambda[2] *= 0.5;  // off the cone: a residual
  EXPECT_GT(complementarity_residual(p).norm(), 0.1);
}

// cone_ratio is |xi| / b, the quantity classify() compares with 1, and traction_on_cone returns
// the trial traction scaled onto the cone's radius b (the return mapping), for points inside and
// outside the cone alike; both are 0 where no cone applies.
TEST(FrictionLaw, ConeRatioAndTractionOnCone) {
  LocalPoint p = slipping_point();
  // b = lambda_n + c_n (d_n - gap0) = 2 + 1.7 * 0.01; xi = lambda_t + c_t (d_t - d_ref).
  const double b = 2.0 + 1.7 * 0.01;
  const Eigen::Vector2d xi(0.7 + 2.3 * 0.8, -0.4 + 2.3 * 0.45);
  EXPECT_NEAR(cone_ratio(p), xi.norm() / b, 1e-14);
  EXPECT_GT(cone_ratio(p), 1.0);
  EXPECT_LT((traction_on_cone(p) - b * xi.normalized()).norm(), 1e-14);
  p.d.tail<2>() = p.d_ref.tail<2>();  // inside the cone: |lambda_t| = 0.806 < b
  EXPECT_EQ(classify(p), NodeStatus::Stick);
  EXPECT_NEAR(cone_ratio(p), std::hypot(0.7, 0.4) / b, 1e-14);
  EXPECT_NEAR(traction_on_cone(p).norm(), b, 1e-14);
  EXPECT_NEAR(traction_on_cone(p).normalized().dot(Eigen::Vector2d(0.7, -0.4).normalized()), 1.0,
              1e-14);
  p.tied = true;
  EXPECT_EQ(cone_ratio(p), 0.0);
  EXPECT_EQ(traction_on_cone(p).norm(), 0.0);
  p.tied = false;
  p.lambda[0] = -1.0;
  p.d[0] = p.gap0 - 0.1;  // open
  EXPECT_EQ(cone_ratio(p), 0.0);
}

}  // namespace
}  // namespace styk::contact
