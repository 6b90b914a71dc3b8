// Gauss-Legendre quadrature on [-1, 1] and its tensor products on the reference hexahedron.
#include <cmath>
#include <stdexcept>
#include <string>

#include "styk/core/element.hpp"

namespace styk {

namespace {

constexpr int kMaxGaussPoints = 6;

// Legendre polynomial P_n(x) and its derivative by the three-term recurrence.
void legendre(int n, double x, double& p, double& dp) {
  double p_prev = 1.0;  // P_0
  p = x;                // P_1
  for (int k = 2; k <= n; ++k) {
    const double p_next = ((2.0 * k - 1.0) * x * p - (k - 1.0) * p_prev) / k;
    p_prev = p;
    p = p_next;
  }
  // (1 - x^2) P_n' = n (P_{n-1} - x P_n); the roots are interior, so 1 - x^2 > 0.
  dp = n * (p_prev - x * p) / (1.0 - x * x);
}

}  // namespace

void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights) {
  if (n < 1 || n > kMaxGaussPoints)
    throw std::invalid_argument("gauss_legendre: " + std::to_string(n) +
                                " points requested, supported are 1.." +
                                std::to_string(kMaxGaussPoints));
  points.assign(n, 0.0);
  weights.assign(n, 0.0);
  if (n == 1) {
    weights[0] = 2.0;
    return;
  }
  const double pi = std::acos(-1.0);
  // Newton on P_n from the classical cosine guess; the roots are simple and well separated for
  // n <= 6, so a few iterations reach round-off. Only the positive half is computed and mirrored
  // so that the rule is exactly symmetric (odd n keeps the exact 0 in the middle).
  for (int i = 0; i < n / 2; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double p = 0.0, dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      legendre(n, x, p, dp);
      const double dx = p / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    legendre(n, x, p, dp);
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    points[n - 1 - i] = x;
    points[i] = -x;
    weights[n - 1 - i] = w;
    weights[i] = w;
  }
  if (n % 2 == 1) {
    double p = 0.0, dp = 1.0;
    legendre(n, 0.0, p, dp);
    weights[n / 2] = 2.0 / (dp * dp);
  }
}

IntegrationRule gauss_rule(int nx, int ny, int nz) {
  std::vector<double> px, wx, py, wy, pz, wz;
  gauss_legendre(nx, px, wx);
  gauss_legendre(ny, py, wy);
  gauss_legendre(nz, pz, wz);
  IntegrationRule rule;
  rule.label = std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz) + " Gauss";
  rule.points.reserve(static_cast<std::size_t>(nx) * ny * nz);
  rule.weights.reserve(static_cast<std::size_t>(nx) * ny * nz);
  // xi fastest, then eta, then zeta: the integration-point numbering of CalculiX (checked with ccx
  // on a single C3D8 under *EL PRINT) and Abaqus, so point k here is point k+1 in their output.
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        rule.points.push_back(Vec3{px[i], py[j], pz[k]});
        rule.weights.push_back(wx[i] * wy[j] * wz[k]);
      }
  return rule;
}

}  // namespace styk
