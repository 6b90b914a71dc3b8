#include "styk/studies/study/plate_series.hpp"

#include <cmath>

namespace styk::studies {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Odd harmonics up to this: the deflection's terms fall as 1/(m n (m^2 + n^2)^2), the moment's
// as 1/(m n (m^2 + n^2)); both sums are converged to better than 1e-7 relative at the centre.
constexpr int kHarmonics = 1999;

// Sums f(m, n) sin(m pi x / a) sin(n pi y / a) over odd m, n.
template <class Term>
double navier_sum(const SquarePlate& p, double x, double y, Term term) {
  double sum = 0.0;
  for (int m = 1; m <= kHarmonics; m += 2) {
    const double sx = std::sin(m * kPi * x / p.side);
    for (int n = 1; n <= kHarmonics; n += 2)
      sum += term(static_cast<double>(m), static_cast<double>(n)) * sx *
             std::sin(n * kPi * y / p.side);
  }
  return sum;
}

}  // namespace

double plate_deflection(const SquarePlate& p, double x, double y, bool mindlin) {
  const double t = p.thickness, nu = p.poisson;
  const double D = p.young * t * t * t / (12.0 * (1.0 - nu * nu));
  const double kGt = 5.0 / 6.0 * p.young / (2.0 * (1.0 + nu)) * t;
  const double a2 = p.side * p.side;
  return navier_sum(p, x, y, [&](double m, double n) {
    const double k2 = (m * m + n * n) * kPi * kPi / a2;  // the harmonic's -Laplacian
    const double load = 16.0 * p.pressure / (kPi * kPi * m * n);
    return load * (1.0 / (D * k2 * k2) + (mindlin ? 1.0 / (kGt * k2) : 0.0));
  });
}

double plate_moment_sum(const SquarePlate& p, double x, double y) {
  const double a2 = p.side * p.side;
  return navier_sum(p, x, y, [&](double m, double n) {
    const double k2 = (m * m + n * n) * kPi * kPi / a2;
    return (1.0 + p.poisson) * 16.0 * p.pressure / (kPi * kPi * m * n * k2);
  });
}

double plate_moment_sum_mean(const SquarePlate& p, double x0, double x1, double y0, double y1) {
  const double a = p.side, a2 = a * a;
  // The mean of sin(m pi x / a) over [x0, x1].
  const auto mean_sin = [a](double m, double lo, double hi) {
    return a / (m * kPi * (hi - lo)) * (std::cos(m * kPi * lo / a) - std::cos(m * kPi * hi / a));
  };
  double sum = 0.0;
  for (int m = 1; m <= kHarmonics; m += 2) {
    const double sx = mean_sin(m, x0, x1);
    for (int n = 1; n <= kHarmonics; n += 2) {
      const double k2 = (static_cast<double>(m) * m + static_cast<double>(n) * n) * kPi * kPi / a2;
      sum += (1.0 + p.poisson) * 16.0 * p.pressure / (kPi * kPi * m * n * k2) * sx *
             mean_sin(n, y0, y1);
    }
  }
  return sum;
}

}  // namespace styk::studies
