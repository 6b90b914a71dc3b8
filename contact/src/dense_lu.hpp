// The dense LU of the active-set iteration's linearised contact system, through LAPACK's dgetrf.
// Debian links it to OpenBLAS, whose kernels are chosen for the CPU at run time and threaded: on
// the development machine (2 cores, AVX2) it factorises n = 7200 in 2.7 s against 14.1 s for
// Eigen's PartialPivLU compiled for generic x86-64 (bench/contact/README.md).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace styk::contact_detail {

class DenseLu {
 public:
  // How the matrix is handed over: A itself, or its transpose (a system assembled row by row of A
  // is contiguous in column-major storage as A^T; LAPACK then factorises A^T and solves with
  // TRANS = 'T', the same arithmetic).
  enum class Storage { plain, transposed };

  // Factorises A (square), given as `storage` says; check factorised() before solving.
  explicit DenseLu(Eigen::MatrixXd A, Storage storage = Storage::plain);

  // False when a pivot is exactly zero.
  bool factorised() const { return info_ == 0; }
  // Reciprocal condition number in the 1-norm (LAPACK dgecon's estimate, as Eigen's rcond()).
  double rcond() const;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  // Solves A x = b for a matrix A close to the factorised one (the same contact system some
  // Newton steps later, a few nodes' statuses changed, so whole rows rewritten): GMRES
  // preconditioned by this factor, up to `max_iterations` (a change of r rows leaves LU^-1 A the
  // identity plus a rank-r term, which GMRES resolves in about r + 1 iterations), then iterative
  // refinement x += LU^-1 (b - A x) while it still lowers the residual. True when the residual it
  // stops at is within a direct solve's backward error, ||b - A x||_inf <= sqrt(n) eps ||A||_inf
  // ||x||_inf (LAPACK dsgesv's test); false otherwise (x is then meaningless and A wants a
  // factorisation of its own). `iterations`: the GMRES iterations taken. A is given in this
  // factor's storage (A^T for Storage::transposed).
  bool solve_by_krylov(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                       int max_iterations, int& iterations) const;

 private:
  struct Preconditioner;
  // Refinement from the given x, up to `max_steps` (see solve_by_krylov).
  bool refine_from(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   int max_steps, int& steps) const;

  Eigen::MatrixXd lu_;  // the LU of the stored matrix (A or A^T)
  bool transposed_ = false;
  std::vector<int> pivots_;
  double norm1_ = 0.0;  // 1-norm of A before factorisation
  int info_ = 0;
};

}  // namespace styk::contact_detail
