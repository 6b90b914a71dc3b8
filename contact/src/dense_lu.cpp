#include "dense_lu.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <unsupported/Eigen/IterativeSolvers>

// LAPACK (Fortran calling convention; OpenBLAS exports these names).
extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda,
             const int* ipiv, double* b, const int* ldb, int* info, std::size_t trans_length);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm,
             double* rcond, double* work, int* iwork, int* info, std::size_t norm_length);
}

namespace styk::contact_detail {

namespace {

// ||M||_1 (largest column sum) and ||M||_inf (largest row sum) of a column-major matrix, each in
// one contiguous sweep.
double largest_column_sum(const Eigen::MatrixXd& M) {
  return M.size() > 0 ? M.cwiseAbs().colwise().sum().maxCoeff() : 0.0;
}
double largest_row_sum(const Eigen::MatrixXd& M) {
  if (M.size() == 0) return 0.0;
  Eigen::VectorXd sums = Eigen::VectorXd::Zero(M.rows());
  for (Eigen::Index c = 0; c < M.cols(); ++c) sums += M.col(c).cwiseAbs();
  return sums.maxCoeff();
}

}  // namespace

// GMRES's preconditioner: this factor's solve.
struct DenseLu::Preconditioner {
  const DenseLu& lu;
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const { return lu.solve(r); }
};

DenseLu::DenseLu(Eigen::MatrixXd A, Storage storage)
    : lu_(std::move(A)), transposed_(storage == Storage::transposed) {
  if (lu_.rows() != lu_.cols()) throw std::invalid_argument("DenseLu: the matrix is not square");
  const int n = static_cast<int>(lu_.rows());
  // ||A||_1 is ||A^T||_inf.
  norm1_ = transposed_ ? largest_row_sum(lu_) : largest_column_sum(lu_);
  pivots_.resize(static_cast<std::size_t>(n));
  if (n > 0) dgetrf_(&n, &n, lu_.data(), &n, pivots_.data(), &info_);
}

double DenseLu::rcond() const {
  const int n = static_cast<int>(lu_.rows());
  if (n == 0) return 1.0;
  if (!factorised()) return 0.0;
  double rcond = 0.0;
  std::vector<double> work(4 * static_cast<std::size_t>(n));
  std::vector<int> iwork(static_cast<std::size_t>(n));
  int info = 0;
  // The 1-norm condition of A is the infinity-norm condition of A^T.
  const char norm = transposed_ ? 'I' : '1';
  dgecon_(&norm, &n, lu_.data(), &n, &norm1_, &rcond, work.data(), iwork.data(), &info, 1);
  return info == 0 ? rcond : 0.0;
}

Eigen::VectorXd DenseLu::solve(const Eigen::VectorXd& b) const {
  const int n = static_cast<int>(lu_.rows());
  Eigen::VectorXd x = b;
  if (n == 0) return x;
  const int nrhs = 1;
  int info = 0;
  const char trans = transposed_ ? 'T' : 'N';
  dgetrs_(&trans, &n, &nrhs, lu_.data(), &n, pivots_.data(), x.data(), &n, &info, 1);
  if (info != 0) throw std::logic_error("DenseLu: dgetrs rejected its arguments");
  return x;
}

bool DenseLu::solve_by_krylov(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                              Eigen::VectorXd& x, int max_iterations, int& iterations) const {
  iterations = 0;
  if (!factorised() || A.rows() != lu_.rows() || A.cols() != lu_.cols() || b.size() != A.rows())
    return false;
  x = solve(b);
  if (!x.allFinite()) return false;
  // Eigen's GMRES (unsupported/Eigen/IterativeSolvers) through its function template, which takes
  // any matrix expression: the stored A^T is used as A^T's transpose without a copy of n^2
  // doubles. No restart: a change of rank r needs about r + 1 iterations.
  const Eigen::Index restart = max_iterations;
  Eigen::Index taken = max_iterations;
  double tolerance = 1e-13;  // of the preconditioned residual: the refinement below finishes
  const Preconditioner preconditioner{*this};
  if (transposed_)
    Eigen::internal::gmres(A.transpose(), b, x, preconditioner, taken, restart, tolerance);
  else
    Eigen::internal::gmres(A, b, x, preconditioner, taken, restart, tolerance);
  iterations = static_cast<int>(taken);
  int steps = 0;
  return refine_from(A, b, x, 2, steps);
}

bool DenseLu::refine_from(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                          int max_steps, int& steps) const {
  steps = 0;
  // ||A||_inf: the row sums of A, the column sums of a stored A^T.
  const double tolerance = std::sqrt(static_cast<double>(A.rows())) *
                           std::numeric_limits<double>::epsilon() *
                           (transposed_ ? largest_column_sum(A) : largest_row_sum(A));
  // Refined while the residual still falls (to the floor of a residual computed in double), as a
  // direct solve's backward error is usually well below the test's bound: the contact iteration's
  // complementarity tolerance needs that accuracy, not just the bound.
  double last = std::numeric_limits<double>::infinity();
  bool reached = false;
  for (;; ++steps) {
    if (!x.allFinite()) return false;
    Eigen::VectorXd r = b;
    if (transposed_)
      r.noalias() -= A.transpose() * x;
    else
      r.noalias() -= A * x;
    const double residual = r.cwiseAbs().maxCoeff();
    if (!(residual < 0.9 * last)) return reached;
    reached = residual <= tolerance * x.cwiseAbs().maxCoeff();
    if (steps == max_steps) return reached;
    last = residual;
    x += solve(r);
  }
}

}  // namespace styk::contact_detail
