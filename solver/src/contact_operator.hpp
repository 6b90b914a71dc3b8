// The contact constraint operator B (3 rows per contact constraint over the active dofs: the
// generalised rows of contact::ContactConstraint) and the pieces of contact::LinearContactSystem
// the structure supplies: the compliance S = B K^-1 B^T (blocked solves with the factor of K), the
// rigid-mode coupling G = B R, and the images B u of displacement fields.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "linear_solver.hpp"
#include "model_constraints.hpp"
#include "prepared_model.hpp"
#include "styk/contact/constraints.hpp"

namespace styk::solver_detail {

class ContactOperator {
 public:
  ContactOperator(const PreparedModel& prepared,
                  const std::vector<contact::ContactConstraint>& constraints);

  int rows() const { return static_cast<int>(ptr_.size()) - 1; }
  // Row i may carry force (normal rows always; tangential rows of frictional constraints).
  bool row_used(int i) const { return used_[i] != 0; }

  Eigen::VectorXd apply(const std::vector<double>& u) const;                // B u (active dofs)
  Eigen::VectorXd apply(const Eigen::Ref<const Eigen::VectorXd>& u) const;  // B u
  void add_transpose(const Eigen::VectorXd& lambda, double factor, std::vector<double>& f) const;
  Eigen::MatrixXd apply_columns(const Eigen::MatrixXd& U) const;  // B U (columns)

  // S = B K_ff^-1 B^T with `solver` prepared on K; unused rows/columns stay zero. Columns are
  // solved in blocks of `block` sparse right-hand sides, the solution wanted only at the contact
  // dofs (LinearSolver::solve_sparse_columns). With *TRANSFORM / *EQUATION / cyclic symmetry
  // (`kinematic` not empty) K is the reduced nodal stiffness P^T R^T K R P, and the contact rows
  // are taken through the same map, S = (B R P) K^-1 (B R P)^T: each column is turned to nodal
  // components and reduced (still sparse: a dependent dof's entry moves to its masters), and the
  // solution is wanted at the reduced dofs the contact nodes are made of.
  Eigen::MatrixXd compliance(LinearSolver& solver, int active_dofs,
                             const ModelConstraints& kinematic, int block = 128) const;

  // The rows of B R P (what `compliance` multiplies K^-1 by): per row, the reduced nodal dofs
  // (active dof numbers of the reduced system) and coefficients; empty for unused rows.
  using ReducedRows = std::vector<std::vector<std::pair<int, double>>>;
  ReducedRows reduced_rows(int active_dofs, const ModelConstraints& kinematic) const;

  // One reduced row as a sparse right-hand side of K. Its dofs not yet among `wanted` (the dofs
  // the solution is wanted at) are appended there; `local` maps an active dof to its index in
  // `wanted`, -1 until it is added.
  static LinearSolver::SparseColumn sparse_column(const std::vector<std::pair<int, double>>& row,
                                                  std::vector<int>& local,
                                                  std::vector<int>& wanted);

 private:
  std::vector<int> ptr_;  // row i: entries ptr_[i] .. ptr_[i+1]
  std::vector<int> dof_;  // active dof
  std::vector<double> value_;
  std::vector<char> used_;
};

// Active nodes touched by a constraint (slave or master), as flags per active node.
std::vector<char> contact_nodes(const PreparedModel& prepared,
                                const std::vector<contact::ContactConstraint>& constraints);

}  // namespace styk::solver_detail
