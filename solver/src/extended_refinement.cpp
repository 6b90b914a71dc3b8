#include "extended_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace styk::solver_detail {
namespace {

double largest_magnitude(const std::vector<double>& v) {
  double m = 0.0;
  for (double value : v) m = std::max(m, std::abs(value));
  return m;
}

}  // namespace

RefinementOutcome refine_in_extended_precision(std::vector<double>& x,
                                               const ExtendedResidual& residual,
                                               const Correction& correct, int max_corrections) {
  constexpr double kSettled = 1e-9;
  RefinementOutcome outcome;
  std::vector<double> r(x.size());
  double previous = std::numeric_limits<double>::infinity();
  for (int k = 0; k < max_corrections; ++k) {
    residual(x, r);
    const std::vector<double> d = correct(r);
    const double size = largest_magnitude(d);
    const double scale = largest_magnitude(x);
    outcome.last_change = scale > 0.0 ? size / scale : size;
    if (!(size <= 0.5 * previous)) break;  // stagnating (or not finite): keep x as it is
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += d[i];
    ++outcome.corrections;
    // The error left after a correction is about the correction times the contraction, and the
    // first correction measures the contraction too (both ~cond(K) x eps): a correction below
    // kSettled leaves an error below kSettled^2, beneath the rounding unit.
    if (size <= kSettled * scale) break;
    previous = size;
  }
  return outcome;
}

std::string describe(const RefinementOutcome& outcome) {
  char last[64];
  std::snprintf(last, sizeof last, "%.2g", outcome.last_change);
  return std::to_string(outcome.corrections) +
         (outcome.corrections == 1 ? " correction" : " corrections") +
         " in extended precision (the last " + last + " of the solution)";
}

long double extended_row_residual(long double b_i, const int* col, const double* values, int count,
                                  const std::vector<double>& x) {
  long double sum = b_i;
  for (int p = 0; p < count; ++p)
    sum -= static_cast<long double>(values[p]) * static_cast<long double>(x[col[p]]);
  return sum;
}

}  // namespace styk::solver_detail
