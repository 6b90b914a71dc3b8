// The structure as the contact iteration sees it when the dense compliance S = B K^-1 B^T would
// not fit (3 m x 3 m doubles: 20 000 frictional constraints need 28.8 GB): the solver layer
// supplies S's action and solves each Newton step as one sparse system with K, so no dense matrix
// over the contact rows is ever formed (docs/contact.md, "Sparse contact solve").
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

namespace styk::contact {

// One Newton step of the active-set iteration (linearised_step.cpp), independent of how S is
// held. For unknown r, the multiplier of generalised row unknowns[r] = 3 j + c of constraint j:
//   q[r] . (d0 - S lambda + G alpha)_(3j .. 3j+2) + sum over (s, v) in coupling[r] of
//   v lambda_(unknowns[s]) = rhs[r] + q[r] . d0_(3j .. 3j+2)
// i.e. rhs already has the loads' part moved right, and qg = q G carries alpha; then the
// equilibrium of the bodies held only by contact, G(unknowns, :)^T lambda = h. Multipliers not
// among the unknowns are zero. `coupling` lists every unknown of the same constraint (zeros
// included), so the pattern depends only on `unknowns`.
struct NewtonRows {
  std::vector<int> unknowns;
  std::vector<Eigen::Vector3d> q;
  std::vector<std::vector<std::pair<int, double>>> coupling;
  Eigen::VectorXd rhs;  // per unknown
  Eigen::MatrixXd qg;   // unknowns x k
  Eigen::MatrixXd g;    // G(unknowns, :), unknowns x k
  Eigen::VectorXd h;    // k
};

class StructureOperator {
 public:
  virtual ~StructureOperator() = default;

  // S's 3x3 diagonal block of constraint j, or an estimate with its null structure (a component
  // that moves nothing has a zero row and column, dependent components stay dependent): the
  // iteration scales its complementarity parameters with it and drops dependent components.
  virtual Eigen::Matrix3d block(int j) const = 0;

  virtual Eigen::VectorXd times(const Eigen::VectorXd& lambda) const = 0;  // S lambda, 3 m

  // Solves `rows` for x = (the unknowns' multipliers, alpha) and gives S lambda of that solution
  // (3 m). False when the system is singular (a body held only by contact not held by the
  // closed constraints). Throws ResourceLimitError when the factor does not fit in memory.
  virtual bool solve(const NewtonRows& rows, Eigen::VectorXd& x, Eigen::VectorXd& s_lambda) = 0;
};

}  // namespace styk::contact
