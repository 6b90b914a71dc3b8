#include "restricted_substitution.hpp"

#include <algorithm>

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
  const Eigen::Index r = X.cols();
  if (E.rows() < max_below_ || E.cols() < r) E.resize(max_below_, r);
  for (SuiteSparse_long s = 0; s < nsuper; ++s) {
    if (!forward[s]) continue;
    const auto [columns, below, block] = supernode_block(s);
    auto xs = X.middleRows(super_[s], columns);
    block.topRows(columns).triangularView<Eigen::Lower>().solveInPlace(xs);
    if (below == 0) continue;
    auto e = E.topLeftCorner(below, r);
    e.noalias() = block.bottomRows(below) * xs;
    const SuiteSparse_long* rows = s_ + pi_[s] + columns;
    for (Eigen::Index i = 0; i < below; ++i) X.row(rows[i]) -= e.row(i);
  }
  for (SuiteSparse_long s = nsuper - 1; s >= 0; --s) {
    if (!back[s]) continue;
    const auto [columns, below, block] = supernode_block(s);
    auto xs = X.middleRows(super_[s], columns);
    if (below > 0) {
      auto e = E.topLeftCorner(below, r);
      const SuiteSparse_long* rows = s_ + pi_[s] + columns;
      for (Eigen::Index i = 0; i < below; ++i) e.row(i) = X.row(rows[i]);
      xs.noalias() -= block.bottomRows(below).transpose() * e;
    }
    block.topRows(columns).triangularView<Eigen::Lower>().transpose().solveInPlace(xs);
  }
}

}  // namespace styk::solver_detail
