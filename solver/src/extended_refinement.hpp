// Iterative refinement of a direct solve with residuals in extended precision (long double: a
// 64-bit significand on x86-64). A backward-stable factorisation leaves a forward error of about
// cond(K) x 2^-53, and that error differs between solvers and orderings: CHOLMOD serially, MUMPS
// over 2 ranks (dynamic scheduling: even between two runs of the same job). Corrections whose
// residual b - K x is computed in extended precision drive x towards the solution of the
// assembled system itself, down to cond(K) x 2^-64 (2048 times smaller; the residual's own
// rounding): every solver then gives the same answer to that level. Measured on a C3D20 beam
// with an *EQUATION and thermal loads (tests/cli/mpi_solve_test.cpp): serial CHOLMOD against
// MUMPS on 2 ranks 6.6e-12 apart without, 1.4e-14 with. Costs a substitution and a product with
// K per correction, usually one.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace styk::solver_detail {

// Fills r = b - K x, computed in extended precision and rounded once (r has x's size).
using ExtendedResidual = std::function<void(const std::vector<double>& x, std::vector<double>& r)>;
// Returns K^-1 r with the kept factor.
using Correction = std::function<std::vector<double>(const std::vector<double>& r)>;

struct RefinementOutcome {
  int corrections = 0;       // corrections applied
  double last_change = 0.0;  // ||d||_inf / ||x||_inf of the last correction computed
};

// "1 correction in extended precision (the last 8.6e-13 of the solution)", for progress lines.
std::string describe(const RefinementOutcome& outcome);

// Refines x in place. Stops after applying a correction of at most 1e-9 of x (the contraction is
// about the first error's relative size, so what is left is ~1e-18, or the residual's own
// rounding cond(K) x 2^-64 where that is larger),
// when a correction is not at most half the one before (not applied: the system is too
// ill-conditioned for refinement to gain), or after `max_corrections`.
RefinementOutcome refine_in_extended_precision(std::vector<double>& x,
                                               const ExtendedResidual& residual,
                                               const Correction& correct, int max_corrections = 4);

// Row i of a CSR matrix (columns index x) against x, subtracted from b_i in extended precision.
long double extended_row_residual(long double b_i, const int* col, const double* values, int count,
                                  const std::vector<double>& x);

}  // namespace styk::solver_detail
