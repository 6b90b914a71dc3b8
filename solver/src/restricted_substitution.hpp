// The contact compliance's solves: a few sparse right-hand sides, a few wanted rows each.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "cholmod_handles.hpp"
#include "linear_solver.hpp"

namespace styk::solver_detail {

// Forward and back substitutions with CHOLMOD's supernodal factor L L^T = P K_ff P^T restricted to
// what a sparse right-hand side and a few wanted rows need. Forward: L y = P b is nonzero only in
// the supernodes on the elimination-tree paths from b's entries to the root (the "reach"); back:
// x_s depends only on x at the rows below supernode s, all of them ancestors of s, so x is exact
// on any ancestor-closed set of supernodes, e.g. the paths from the wanted rows to the root. The
// arithmetic is the full solve's minus exact zeros and unwanted entries.
class RestrictedSubstitution {
 public:
  RestrictedSubstitution(const cholmod_factor& L, const DofPartition& partition);

  // Permuted position of an active dof, -1 when it is prescribed.
  SuiteSparse_long position(int dof) const {
    const int free = partition_.free_of_dof[dof];
    return free < 0 ? -1 : static_cast<SuiteSparse_long>(position_[free]);
  }
  SuiteSparse_long supernode(SuiteSparse_long position) const { return supernode_of_[position]; }
  std::size_t supernodes() const { return parent_.size(); }

  // Marks `s` and its ancestors.
  void mark_path(SuiteSparse_long s, std::vector<char>& marked) const {
    for (; s >= 0 && !marked[s]; s = parent_[s]) marked[s] = 1;
  }

  // X (permuted rows, one column per right-hand side) := L^-1 X on the supernodes `forward`, then
  // L^-T X on `back` (ancestor-closed). E is scratch.
  void solve(Eigen::MatrixXd& X, const std::vector<char>& forward, const std::vector<char>& back,
             Eigen::MatrixXd& E) const;

 private:
  struct Block {
    Eigen::Index columns, below;
    Eigen::Map<const Eigen::MatrixXd> values;  // rows x columns, column-major
  };
  Block supernode_block(SuiteSparse_long s) const {
    const Eigen::Index columns = super_[s + 1] - super_[s];
    const Eigen::Index rows = pi_[s + 1] - pi_[s];
    return {columns, rows - columns, Eigen::Map<const Eigen::MatrixXd>(x_ + px_[s], rows, columns)};
  }

  const DofPartition& partition_;
  std::vector<std::size_t> position_;           // free index -> permuted position
  std::vector<SuiteSparse_long> supernode_of_;  // permuted position -> supernode
  std::vector<SuiteSparse_long> parent_;        // supernodal elimination tree
  const SuiteSparse_long *super_ = nullptr, *pi_ = nullptr, *px_ = nullptr, *s_ = nullptr;
  const double* x_ = nullptr;
  Eigen::Index max_below_ = 0;  // most rows below a diagonal block
};

}  // namespace styk::solver_detail
