// The active-set step's dense solve (contact/src/dense_lu.hpp): a kept factor solves a nearby
// system (a later Newton step's) by GMRES and refinement to a direct solve's accuracy, and
// refuses one it cannot.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <cstdlib>

#include "dense_lu.hpp"

namespace {

using styk::contact_detail::DenseLu;

// A random nonsymmetric matrix with a prescribed 2-norm condition number: U diag(sigma) V^T,
// singular values spaced geometrically from 1 to 1 / condition.
Eigen::MatrixXd with_condition(int n, double condition, unsigned seed) {
  std::srand(seed);
  const Eigen::HouseholderQR<Eigen::MatrixXd> u(Eigen::MatrixXd::Random(n, n));
  const Eigen::HouseholderQR<Eigen::MatrixXd> v(Eigen::MatrixXd::Random(n, n));
  Eigen::VectorXd sigma(n);
  for (int i = 0; i < n; ++i) sigma[i] = std::pow(condition, -static_cast<double>(i) / (n - 1));
  const Eigen::MatrixXd U = u.householderQ();
  const Eigen::MatrixXd V = v.householderQ();
  return U * sigma.asDiagonal() * V.transpose();
}

double relative_error(const Eigen::VectorXd& x, const Eigen::VectorXd& reference) {
  return (x - reference).norm() / reference.norm();
}

TEST(DenseLu, SolvesToTheDirectSolutionsAccuracy) {
  const Eigen::MatrixXd A = with_condition(300, 1e6, 3);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(300, -1.0, 2.0);
  const Eigen::VectorXd reference = A.fullPivLu().solve(b);
  const DenseLu lu(A);
  ASSERT_TRUE(lu.factorised());
  // cond 1e6: forward error <= cond * small multiple of eps ~ 1e-9.
  EXPECT_LT(relative_error(lu.solve(b), reference), 1e-8);
  // LAPACK's 1-norm estimate of a 2-norm condition of 1e6: within a factor of ~n.
  EXPECT_LT(lu.rcond(), 1e-5);
  EXPECT_GT(lu.rcond(), 1e-9);
}

TEST(DenseLu, SolvesANearbySystemWithTheOldFactor) {
  const int n = 300;
  const Eigen::MatrixXd A = with_condition(n, 1e4, 5);
  // The next system: A changed by 1e-6 of its norm in 30 rows (a Newton step's slip rows).
  Eigen::MatrixXd next = A;
  std::srand(11);
  next.topRows(30) += 1e-6 * Eigen::MatrixXd::Random(30, n);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  const Eigen::VectorXd reference = next.fullPivLu().solve(b);
  const DenseLu old_factor(A);
  // The old factor alone is off by about cond * 1e-6 * sqrt(30 n).
  EXPECT_GT(relative_error(old_factor.solve(b), reference), 1e-4);
  Eigen::VectorXd x;
  int iterations = 0;
  ASSERT_TRUE(old_factor.solve_by_krylov(next, b, x, 10, iterations));
  EXPECT_GE(iterations, 2);
  EXPECT_LE(iterations, 10);
  // As accurate as a direct solve of `next` (cond 1e4: ~1e-12).
  EXPECT_LT(relative_error(x, reference), 1e-11);
  EXPECT_LT(relative_error(DenseLu(next).solve(b), reference), 1e-11);
}

// Statuses of a few nodes changed: r whole rows rewritten (not a small change), which LU^-1 A
// turns into the identity plus a rank-r term. GMRES with the old factor resolves it in r + 1
// iterations at most (r = 6 here; with a budget of 10), to a direct solve's accuracy; a budget
// below r + 1 is refused.
TEST(DenseLu, ResolvesRewrittenRowsInAboutAsManyIterations) {
  const int n = 300, r = 6;
  const Eigen::MatrixXd A = with_condition(n, 1e4, 21);
  Eigen::MatrixXd next = A;
  std::srand(23);
  next.middleRows(100, r) = Eigen::MatrixXd::Random(r, n);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  const Eigen::VectorXd reference = next.fullPivLu().solve(b);
  const DenseLu old_factor(A);
  Eigen::VectorXd x;
  int iterations = 0;
  ASSERT_TRUE(old_factor.solve_by_krylov(next, b, x, 10, iterations));
  EXPECT_LE(iterations, r + 1);
  EXPECT_LT(relative_error(x, reference), 1e-10);
  EXPECT_FALSE(old_factor.solve_by_krylov(next, b, x, r - 2, iterations));
}

// The contact step hands over A^T (assembled row by row of A): the same solution and condition
// estimate as A itself, and the solve with the old factor with a stored transpose.
TEST(DenseLu, TransposedStorageSolvesWithA) {
  const int n = 250;
  const Eigen::MatrixXd A = with_condition(n, 1e4, 13);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, -3.0);
  const Eigen::VectorXd reference = A.fullPivLu().solve(b);
  const DenseLu plain(A);
  const DenseLu transposed(A.transpose(), DenseLu::Storage::transposed);
  ASSERT_TRUE(transposed.factorised());
  EXPECT_LT(relative_error(transposed.solve(b), reference), 1e-11);
  // Both estimate the 1-norm condition of A (LAPACK's estimator: within a small factor).
  EXPECT_GT(transposed.rcond(), plain.rcond() / 3.0);
  EXPECT_LT(transposed.rcond(), plain.rcond() * 3.0);
  Eigen::MatrixXd next = A;
  std::srand(17);
  next.topRows(20) += 1e-6 * Eigen::MatrixXd::Random(20, n);
  Eigen::VectorXd x;
  int iterations = 0;
  ASSERT_TRUE(transposed.solve_by_krylov(next.transpose(), b, x, 10, iterations));
  EXPECT_LT(relative_error(x, next.fullPivLu().solve(b)), 1e-11);
}

TEST(DenseLu, RefusesASystemTooFarFromTheFactor) {
  const int n = 200;
  const DenseLu old_factor(with_condition(n, 1e4, 7));
  const Eigen::MatrixXd other = with_condition(n, 1e4, 8);
  Eigen::VectorXd x;
  int iterations = 0;
  EXPECT_FALSE(old_factor.solve_by_krylov(other, Eigen::VectorXd::Ones(n), x, 10, iterations));
  EXPECT_EQ(iterations, 10);
  // And one that would need more iterations than allowed (20 rows changed, 2 allowed).
  Eigen::MatrixXd next = with_condition(n, 1e4, 7);
  next.topRows(20) += 2e-2 * Eigen::MatrixXd::Random(20, n);
  EXPECT_FALSE(old_factor.solve_by_krylov(next, Eigen::VectorXd::Ones(n), x, 2, iterations));
}

TEST(DenseLu, SingularSystemsAreReported) {
  Eigen::MatrixXd A = with_condition(50, 10.0, 9);
  A.row(7).setZero();
  const DenseLu lu(A);
  EXPECT_TRUE(!lu.factorised() || lu.rcond() < 1e-15);
}

}  // namespace
