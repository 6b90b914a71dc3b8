#include "restricted_substitution.hpp"

#include <algorithm>

#include "blas_kernels.hpp"

namespace styk::solver_detail {

RestrictedSubstitution::RestrictedSubstitution(const cholmod_factor& L,
                                               const DofPartition& partition)
    : partition_(partition) {
  const auto n = static_cast<std::size_t>(L.n);
  const auto* perm = static_cast<const SuiteSparse_long*>(L.Perm);
  position_.resize(n);
  for (std::size_t k = 0; k < n; ++k) position_[perm != nullptr ? perm[k] : k] = k;
  super_ = static_cast<const SuiteSparse_long*>(L.super);
  pi_ = static_cast<const SuiteSparse_long*>(L.pi);
  px_ = static_cast<const SuiteSparse_long*>(L.px);
  s_ = static_cast<const SuiteSparse_long*>(L.s);
  x_ = static_cast<const double*>(L.x);
  const auto nsuper = static_cast<SuiteSparse_long>(L.nsuper);
  supernode_of_.resize(n);
  parent_.assign(nsuper, -1);
  for (SuiteSparse_long s = 0; s < nsuper; ++s) {
    for (SuiteSparse_long k = super_[s]; k < super_[s + 1]; ++k) supernode_of_[k] = s;
    // The first row below the diagonal block belongs to the parent in the supernodal tree.
    const SuiteSparse_long columns = super_[s + 1] - super_[s];
    if (pi_[s + 1] - pi_[s] > columns) parent_[s] = s_[pi_[s] + columns];
    max_below_ = std::max<Eigen::Index>(max_below_, pi_[s + 1] - pi_[s] - columns);
  }
  for (SuiteSparse_long s = 0; s < nsuper; ++s)
    if (parent_[s] >= 0) parent_[s] = supernode_of_[parent_[s]];
}

void RestrictedSubstitution::solve(Eigen::MatrixXd& X, const std::vector<char>& forward,
                                   const std::vector<char>& back, Eigen::MatrixXd& E) const {
  const auto nsuper = static_cast<SuiteSparse_long>(parent_.size());
  const auto r = static_cast<int>(X.cols());
  const auto ldx = static_cast<int>(X.rows());
  if (E.rows() < max_below_ || E.cols() < r) E.resize(max_below_, r);
  const auto lde = static_cast<int>(E.rows());
  for (SuiteSparse_long s = 0; s < nsuper; ++s) {
    if (!forward[s]) continue;
    const auto [columns, below, block] = supernode_block(s);
    const auto c = static_cast<int>(columns), b = static_cast<int>(below);
    const auto ldl = static_cast<int>(block.rows());
    double* xs = X.data() + super_[s];
    lower_triangular_solve(false, c, r, block.data(), ldl, xs, ldx);
    if (below == 0) continue;
    E.topLeftCorner(below, r).setZero();
    multiply_add(false, b, r, c, 1.0, block.data() + columns, ldl, xs, ldx, E.data(), lde);
    const SuiteSparse_long* rows = s_ + pi_[s] + columns;
    for (Eigen::Index i = 0; i < below; ++i) X.row(rows[i]) -= E.row(i).head(r);
  }
  for (SuiteSparse_long s = nsuper - 1; s >= 0; --s) {
    if (!back[s]) continue;
    const auto [columns, below, block] = supernode_block(s);
    const auto c = static_cast<int>(columns), b = static_cast<int>(below);
    const auto ldl = static_cast<int>(block.rows());
    double* xs = X.data() + super_[s];
    if (below > 0) {
      const SuiteSparse_long* rows = s_ + pi_[s] + columns;
      for (Eigen::Index i = 0; i < below; ++i) E.row(i).head(r) = X.row(rows[i]);
      multiply_add(true, c, r, b, -1.0, block.data() + columns, ldl, E.data(), lde, xs, ldx);
    }
    lower_triangular_solve(true, c, r, block.data(), ldl, xs, ldx);
  }
}

}  // namespace styk::solver_detail
