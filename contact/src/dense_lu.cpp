#include "dense_lu.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

// LAPACK (Fortran calling convention; OpenBLAS exports these names).
extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda,
             const int* ipiv, double* b, const int* ldb, int* info, std::size_t trans_length);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm,
             double* rcond, double* work, int* iwork, int* info, std::size_t norm_length);
}

namespace styk::contact_detail {

DenseLu::DenseLu(Eigen::MatrixXd A) : lu_(std::move(A)) {
  if (lu_.rows() != lu_.cols()) throw std::invalid_argument("DenseLu: the matrix is not square");
  const int n = static_cast<int>(lu_.rows());
  norm1_ = n > 0 ? lu_.cwiseAbs().colwise().sum().maxCoeff() : 0.0;
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
  const char norm = '1';
  dgecon_(&norm, &n, lu_.data(), &n, &norm1_, &rcond, work.data(), iwork.data(), &info, 1);
  return info == 0 ? rcond : 0.0;
}

Eigen::VectorXd DenseLu::solve(const Eigen::VectorXd& b) const {
  const int n = static_cast<int>(lu_.rows());
  Eigen::VectorXd x = b;
  if (n == 0) return x;
  const int nrhs = 1;
  int info = 0;
  const char trans = 'N';
  dgetrs_(&trans, &n, &nrhs, lu_.data(), &n, pivots_.data(), x.data(), &n, &info, 1);
  if (info != 0) throw std::logic_error("DenseLu: dgetrs rejected its arguments");
  return x;
}

bool DenseLu::refine(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                     int max_steps, int& steps) const {
  steps = 0;
  if (!factorised() || A.rows() != lu_.rows() || A.cols() != lu_.cols() || b.size() != A.rows())
    return false;
  const double tolerance = std::sqrt(static_cast<double>(A.rows())) *
                           std::numeric_limits<double>::epsilon() *
                           A.cwiseAbs().rowwise().sum().maxCoeff();
  // Refined while the residual still falls (to the floor of a residual computed in double), as a
  // direct solve's backward error is usually well below the test's bound: the contact iteration's
  // complementarity tolerance needs that accuracy, not just the bound.
  x = solve(b);
  double last = std::numeric_limits<double>::infinity();
  bool reached = false;
  for (;; ++steps) {
    if (!x.allFinite()) return false;
    Eigen::VectorXd r = b;
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
