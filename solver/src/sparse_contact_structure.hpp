// The contact iteration's view of the structure without the dense compliance S (docs/contact.md,
// "Sparse contact solve"): each Newton step is one sparse LU (MUMPS) of K augmented with the
// closed contact rows, S lambda comes from the factor of K, and S's diagonal blocks are
// estimated from K's diagonal, calibrated against exact blocks of a sample of constraints.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "augmented_lu.hpp"
#include "contact_operator.hpp"
#include "linear_solver.hpp"
#include "stiffness_matrix.hpp"
#include "styk/contact/structure_operator.hpp"

namespace styk::solver_detail {

class SparseContactStructure final : public contact::StructureOperator {
 public:
  // K: the pristine reduced stiffness, read before a solver is prepared on it (its free part is
  // copied: the factor may release K's values); `rows`: ContactOperator::reduced_rows.
  SparseContactStructure(const StiffnessMatrix& K, const DofPartition& partition,
                         ContactOperator::ReducedRows rows, int active_dofs);
  ~SparseContactStructure() override;

  // The factor of K_ff (prepared with the same partition; kept alive by the caller for this
  // object's lifetime): S lambda is solved with it, and the block estimate is calibrated.
  void attach(LinearSolver& solver);

  Eigen::Matrix3d block(int j) const override { return blocks_[j]; }
  Eigen::VectorXd times(const Eigen::VectorXd& lambda) const override;
  bool solve(const contact::NewtonRows& rows, Eigen::VectorXd& x,
             Eigen::VectorXd& s_lambda) override;

  double calibration() const { return calibration_; }  // exact / estimated self-compliance
  int factorisations() const;                          // numeric LU factorisations so far
  int reused() const;  // Newton steps solved by refinement with an earlier factor

 private:
  void estimate_blocks();
  void calibrate_blocks();

  DofPartition partition_;
  ContactOperator::ReducedRows rows_;                           // reduced active dofs
  std::vector<std::vector<std::pair<int, double>>> free_rows_;  // the same over free indices
  // Rows with free dofs ("carried": every Newton step's system has a multiplier for each, zero
  // unless it is an unknown) and each one's place among them; -1 for the others.
  std::vector<int> position_;
  long carried_ = 0;
  LinearSolver* solver_ = nullptr;
  int active_dofs_;
  // K_ff as CSR over free indices, both triangles, columns sorted.
  std::vector<long> k_ptr_, k_col_;
  std::vector<double> k_value_;
  std::vector<Eigen::Matrix3d> blocks_;
  double calibration_ = 1.0;
  std::unique_ptr<AugmentedLu> lu_;
};

}  // namespace styk::solver_detail
