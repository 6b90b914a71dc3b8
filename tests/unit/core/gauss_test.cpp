// Gauss-Legendre rules and their tensor products.
#include <cmath>

#include <gtest/gtest.h>

#include "styk/core/element.hpp"

namespace styk {
namespace {

// An n-point Gauss-Legendre rule integrates x^k over [-1, 1] exactly for k <= 2n - 1
// (2/(k+1) for even k, 0 for odd k) but misses x^(2n) (by 7.4e-4 at n = 6, more for smaller n);
// tolerance 1e-14.
TEST(GaussLegendre, ExactUpToDegreeTwoNMinusOne) {
  for (int n = 1; n <= 6; ++n) {
    std::vector<double> x, w;
    gauss_legendre(n, x, w);
    ASSERT_EQ(static_cast<int>(x.size()), n);
    ASSERT_EQ(static_cast<int>(w.size()), n);
    for (int k = 0; k <= 2 * n; ++k) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += w[i] * std::pow(x[i], k);
      const double exact = k % 2 == 0 ? 2.0 / (k + 1) : 0.0;
      if (k <= 2 * n - 1)
        EXPECT_NEAR(sum, exact, 1e-14) << "n=" << n << " k=" << k;
      else
        EXPECT_GT(std::abs(sum - exact), 1e-4) << "n=" << n << " k=" << k;
    }
    for (int i = 1; i < n; ++i) EXPECT_LT(x[i - 1], x[i]);  // ascending
  }
}

// Tabulated values (Abramowitz & Stegun 25.4.30): n=2 x=1/sqrt(3); n=3 x=sqrt(3/5), w=5/9, 8/9;
// n=6 largest x=0.932469514203152, w=0.171324492379170. Tolerance 1e-15.
TEST(GaussLegendre, MatchesTabulatedValues) {
  std::vector<double> x, w;
  gauss_legendre(2, x, w);
  EXPECT_NEAR(x[1], 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(w[0], 1.0, 1e-15);
  gauss_legendre(3, x, w);
  EXPECT_EQ(x[1], 0.0);
  EXPECT_NEAR(x[2], std::sqrt(0.6), 1e-15);
  EXPECT_NEAR(w[0], 5.0 / 9.0, 1e-15);
  EXPECT_NEAR(w[1], 8.0 / 9.0, 1e-15);
  gauss_legendre(6, x, w);
  EXPECT_NEAR(x[5], 0.932469514203152, 1e-15);
  EXPECT_NEAR(w[5], 0.171324492379170, 1e-15);
  EXPECT_EQ(x[0], -x[5]);
}

TEST(GaussLegendre, RejectsUnsupportedCounts) {
  std::vector<double> x, w;
  EXPECT_THROW(gauss_legendre(0, x, w), std::invalid_argument);
  EXPECT_THROW(gauss_legendre(7, x, w), std::invalid_argument);
}

// CalculiX numbering (checked with ccx 2.x on one C3D8 under *EL PRINT, E): xi fastest, then eta,
// then zeta.
TEST(GaussRule, PointOrderIsXiFastestThenEtaThenZeta) {
  const IntegrationRule rule = gauss_rule(2, 3, 2);
  ASSERT_EQ(rule.size(), 12);
  EXPECT_EQ(rule.label, "2x3x2 Gauss");
  const double a = 1.0 / std::sqrt(3.0), b = std::sqrt(0.6);
  EXPECT_NEAR(rule.points[0][0], -a, 1e-15);
  EXPECT_NEAR(rule.points[0][1], -b, 1e-15);
  EXPECT_NEAR(rule.points[0][2], -a, 1e-15);
  EXPECT_NEAR(rule.points[1][0], a, 1e-15);    // xi moves first
  EXPECT_NEAR(rule.points[2][1], 0.0, 1e-15);  // then eta
  EXPECT_NEAR(rule.points[6][2], a, 1e-15);    // then zeta
  EXPECT_NEAR(rule.points[6][0], -a, 1e-15);
  double volume = 0.0;
  for (double w : rule.weights) volume += w;
  EXPECT_NEAR(volume, 8.0, 1e-14);
  EXPECT_NEAR(rule.weights[2], 1.0 * 8.0 / 9.0 * 1.0, 1e-15);
}

}  // namespace
}  // namespace styk
