// The active-set step's dense LU (contact/src/dense_lu.hpp): LAPACK dgetrf through OpenBLAS against
// Eigen's PartialPivLU, on the same random diagonally weighted matrices, factorise + rcond + one
// solve each, as the step does. Usage: styk_bench_dense_lu [n ...] (default 1000 3000 7200).
#include <Eigen/LU>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "dense_lu.hpp"

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty()) sizes = {1000, 3000, 7200};
  std::printf(
      "| n | Eigen PartialPivLU s | LAPACK (OpenBLAS) s | ratio | max |x_eigen - x_lapack| |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const int n : sizes) {
    std::srand(7);
    const Eigen::MatrixXd A =
        Eigen::MatrixXd::Random(n, n) + 0.1 * n * Eigen::MatrixXd::Identity(n, n);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    auto start = std::chrono::steady_clock::now();
    const Eigen::PartialPivLU<Eigen::MatrixXd> eigen_lu(A);
    const double eigen_rcond = eigen_lu.rcond();
    const Eigen::VectorXd x_eigen = eigen_lu.solve(b);
    const double eigen_s = seconds_since(start);
    start = std::chrono::steady_clock::now();
    const styk::contact_detail::DenseLu lapack_lu(A);
    const double lapack_rcond = lapack_lu.rcond();
    const Eigen::VectorXd x_lapack = lapack_lu.solve(b);
    const double lapack_s = seconds_since(start);
    std::printf("| %d | %.2f | %.2f | %.1f | %.1e (rcond %.3g / %.3g) |\n", n, eigen_s, lapack_s,
                eigen_s / lapack_s, (x_eigen - x_lapack).cwiseAbs().maxCoeff(), eigen_rcond,
                lapack_rcond);
  }
  return 0;
}
