// *EQUATION: linear multi-point constraints sum c_i w_i = 0 on nodal dofs (local for nodes with a
// *TRANSFORM), enforced exactly by eliminating the first term's dof:
//   w_d = sum_j a_dj w_j,   a_dj = -c_j / c_0,
// with chains (a term that is itself the first term of another equation) substituted until every
// right-hand dof is independent (free or prescribed). With P = the map from the independent dofs
// to all dofs, the system becomes P^T K P w = P^T f. The solver keeps it in the active-dof layout:
// the rows and columns of the dependent dofs are zeroed and the dependent dofs are handed to the
// linear solver as prescribed (value 0), so CHOLMOD and the prescribed-dof elimination work
// unchanged; the node graph is widened beforehand (extra_node_couplings) so P^T K P fits it.
#pragma once

#include <utility>
#include <vector>

#include "prepared_model.hpp"
#include "stiffness_matrix.hpp"

namespace styk::solver_detail {

struct DependentDof {
  int dof = 0;                                  // nodal active dof
  std::vector<std::pair<int, double>> masters;  // (independent dof, a_dj), dof-sorted
  SourceLoc where;                              // the *EQUATION that eliminates it
};

class EquationElimination {
 public:
  // Resolves the model's equations and the `generated` ones (cyclic symmetry, which may have a
  // single term: that dof is zero). Throws InputError at an equation's line for a term on a node
  // no element uses, a dependent dof eliminated twice, or dependencies that form a cycle.
  static EquationElimination build(const Model& model, const PreparedModel& prepared,
                                   const std::vector<Equation>& generated = {});

  bool empty() const { return dependents_.empty(); }
  const std::vector<DependentDof>& dependents() const { return dependents_; }
  std::vector<int> dependent_dofs() const;  // sorted
  // Every dof that appears in an equation (where the constraint exerts a force), sorted.
  const std::vector<int>& involved_dofs() const { return involved_; }

  // Throws InputError at the equation's line when its dependent dof is also prescribed.
  void check_not_prescribed(const Model& model, const PreparedModel& prepared,
                            const std::vector<int>& prescribed) const;

  // Pairs of active nodes that P^T K P couples although no element holds both.
  std::vector<std::pair<int, int>> extra_node_couplings(const Model& model,
                                                        const PreparedModel& prepared) const;

  // K <- P^T K P in place (dependent rows and columns become zero). K's pattern must contain
  // extra_node_couplings().
  void eliminate(StiffnessMatrix& K) const;
  void reduce(std::vector<double>& f) const;  // f <- P^T f (dependent entries become 0)
  void expand(std::vector<double>& w) const;  // w_d <- sum_j a_dj w_j

 private:
  std::vector<DependentDof> dependents_;  // sorted by dof
  std::vector<int> involved_;
};

}  // namespace styk::solver_detail
