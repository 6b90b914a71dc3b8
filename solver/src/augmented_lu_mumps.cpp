// AugmentedLu with MUMPS (sequential, through PETSc's MATSOLVERMUMPS). Measured against UMFPACK
// (symmetric strategy, METIS) on the 2601-node flat joint of bench/contact/write_plate_stack.py:
// 2.0-2.8 s per factorisation against 10-12 s, half the memory.
#include <petscmat.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "augmented_lu.hpp"
#include "petsc_runtime.hpp"
#include "styk/core/diagnostics.hpp"

namespace styk::solver_detail {
namespace {

// MUMPS sizes its workspace from the analysis plus ICNTL(14) percent; the constraint rows' zero
// diagonals delay pivots beyond the default margin (20-35 %: the 441-node flat joint already
// ran out), so it starts at 100 % and grows fourfold on a shortage, up to 1600 %.
constexpr int kFirstWorkspaceMargin = 100;
constexpr int kLastWorkspaceMargin = 1600;
// Steps of iterative refinement after the first solve (AugmentedLu::refine): without them the
// backward error was 1e-10 .. 3e-9 on the flat joint, short of what the contact iteration's 1e-9
// tolerance needs; it stops early at round-off.
constexpr int kRefinementSteps = 3;
constexpr double kConvergedBackwardError = 1e-15;
// A solve whose componentwise backward error stays above this is of a numerically singular system
// (a body held only by contact that the closed rows do not hold).
constexpr double kSingularBackwardError = 1e-8;

}  // namespace

struct AugmentedLu::Mumps {
  Mat factor = nullptr;
  int margin = kFirstWorkspaceMargin;

  ~Mumps() { drop(); }
  void drop() {
    if (factor != nullptr) MatDestroy(&factor);
  }

  // The analysis of A's pattern (MUMPS orders with METIS).
  void analyse(Mat A) {
    MatFactorInfo info;
    MatFactorInfoInitialize(&info);
    petsc_check(MatGetFactor(A, MATSOLVERMUMPS, MAT_FACTOR_LU, &factor), "MatGetFactor");
    petsc_check(MatMumpsSetIcntl(factor, 7, 5), "MatMumpsSetIcntl(7)");  // METIS
    petsc_check(MatMumpsSetIcntl(factor, 14, margin), "MatMumpsSetIcntl(14)");
    petsc_check(MatLUFactorSymbolic(factor, A, nullptr, nullptr, &info), "MatLUFactorSymbolic");
  }

  // The numeric factorisation; the error MUMPS reported (PETSc's MatFactorError).
  MatFactorError factorise(Mat A) {
    MatFactorInfo info;
    MatFactorInfoInitialize(&info);
    const PetscErrorCode code = MatLUFactorNumeric(factor, A, &info);
    MatFactorError error = MAT_FACTOR_NOERROR;
    MatFactorGetError(factor, &error);
    return code != 0 && error == MAT_FACTOR_NOERROR ? MAT_FACTOR_OTHER : error;
  }
};

AugmentedLu::AugmentedLu() : mumps_(std::make_unique<Mumps>()) {}
AugmentedLu::~AugmentedLu() = default;

namespace {

// Rows scaled to a largest entry of 1, then columns likewise. The rows mix K's scale (E h) with
// the constraint rows' (1 on stick and normal rows, the complementarity parameters ~ K's on slip
// rows); unscaled, MUMPS' threshold pivoting left a backward error of 1e-4 on the SPEC 3.2.3
// cantilevers (E = 2e11).
struct Equilibrated {
  std::vector<double> value, row, column;  // scaled entries; the row and column factors
};

Equilibrated equilibrate(const AugmentedMatrix& A) {
  Equilibrated e;
  e.value = A.value;
  e.row.assign(A.size(), 1.0);
  e.column.assign(A.size(), 0.0);
  for (int i = 0; i < A.size(); ++i) {
    double largest = 0.0;
    for (int p = A.ptr[i]; p < A.ptr[i + 1]; ++p) largest = std::max(largest, std::abs(A.value[p]));
    if (largest > 0.0) e.row[i] = 1.0 / largest;
    for (int p = A.ptr[i]; p < A.ptr[i + 1]; ++p) {
      e.value[p] *= e.row[i];
      e.column[A.col[p]] = std::max(e.column[A.col[p]], std::abs(e.value[p]));
    }
  }
  for (double& c : e.column) c = c > 0.0 ? 1.0 / c : 1.0;
  for (int i = 0; i < A.size(); ++i)
    for (int p = A.ptr[i]; p < A.ptr[i + 1]; ++p) e.value[p] *= e.column[A.col[p]];
  return e;
}

}  // namespace

bool AugmentedLu::solve(const AugmentedMatrix& A, const std::vector<double>& b,
                        std::vector<double>& x) {
  PetscRuntime::ensure();
  const PetscInt n = A.size();
  Equilibrated scaled = equilibrate(A);
  Mat M = nullptr;
  // PETSc only reads the index arrays (the factor copies the values).
  petsc_check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, n, n, const_cast<int*>(A.ptr.data()),
                                        const_cast<int*>(A.col.data()), scaled.value.data(), &M),
              "MatCreateSeqAIJWithArrays");
  MatFactorError error = MAT_FACTOR_NOERROR;
  // Analysed anew for every matrix: MUMPS' column permutation (a maximum transversal that puts
  // large entries on the constraint rows' zero diagonals) is computed from the analysed values,
  // and one analysis kept from a step whose slip rows were still stick rows left a backward error
  // of 1e-5 on the SPEC 3.2.3 cantilevers; without the permutation the 2601-node flat joint
  // took 13x longer. The analysis is a few percent of a factorisation.
  mumps_->drop();
  for (;;) {
    if (mumps_->factor == nullptr) mumps_->analyse(M);
    error = mumps_->factorise(M);
    ++factorisations_;
    if (error != MAT_FACTOR_OUTMEMORY || mumps_->margin >= kLastWorkspaceMargin) break;
    mumps_->drop();  // a factor in error stays so: analyse again with more room
    mumps_->margin *= 4;
  }
  if (error != MAT_FACTOR_NOERROR) {
    mumps_->drop();
    MatDestroy(&M);
    if (error == MAT_FACTOR_OUTMEMORY)
      throw ResourceLimitError(
          "sparse contact solve: MUMPS ran out of memory for the LU factor of the stiffness with "
          "the contact rows (" +
          std::to_string(n) + " unknowns); --contact-solver dense when the contact rows are few");
    if (error == MAT_FACTOR_NUMERIC_ZEROPIVOT || error == MAT_FACTOR_STRUCT_ZEROPIVOT) return false;
    throw std::runtime_error("sparse contact solve: MUMPS failed to factorise (PETSc error " +
                             std::to_string(static_cast<int>(error)) + ")");
  }
  MatDestroy(&M);
  return refine(A, scaled.row, scaled.column, b, x) <= kSingularBackwardError;
}

// x = A^-1 b through the equilibrated factor, then iterative refinement on A itself while the
// componentwise backward error falls (MUMPS' own refinement, ICNTL(10), left 4e-6 on the
// cantilevers' slip rows; three steps of this bring it to ~1e-15).
double AugmentedLu::refine(const AugmentedMatrix& A, const std::vector<double>& row,
                           const std::vector<double>& column, const std::vector<double>& b,
                           std::vector<double>& x) const {
  const int n = A.size();
  std::vector<double> residual = b, next_residual(n), correction(n, 0.0);
  std::fill(x.begin(), x.end(), 0.0);
  double error = std::numeric_limits<double>::infinity();
  for (int step = 0; step <= kRefinementSteps; ++step) {
    std::vector<double> rhs(n);
    for (int i = 0; i < n; ++i) rhs[i] = row[i] * residual[i];
    solve_scaled(rhs, correction);
    std::vector<double> next = x;
    for (int i = 0; i < n; ++i) next[i] += column[i] * correction[i];
    // One pass over A for both: the error decides, the residual feeds the next step.
    const double next_error = backward_error(A, next, b, &next_residual);
    if (!(next_error < error)) break;
    x = std::move(next);
    std::swap(residual, next_residual);
    error = next_error;
    if (error <= kConvergedBackwardError) break;
  }
  return error;
}

void AugmentedLu::solve_scaled(std::vector<double>& rhs, std::vector<double>& solution) const {
  const PetscInt n = static_cast<PetscInt>(rhs.size());
  Vec vb = nullptr, vx = nullptr;
  petsc_check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, rhs.data(), &vb),
              "VecCreateSeqWithArray");
  petsc_check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, solution.data(), &vx),
              "VecCreateSeqWithArray");
  const PetscErrorCode solved = MatSolve(mumps_->factor, vb, vx);
  VecDestroy(&vb);
  VecDestroy(&vx);
  petsc_check(solved, "MatSolve");
}

bool augmented_lu_available() { return true; }

}  // namespace styk::solver_detail
