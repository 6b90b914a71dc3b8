// The kinematic constraints of a model beyond plain *BOUNDARY: *TRANSFORM (nodal systems) and
// *EQUATION (eliminated dofs), and what the linear static path does with them. The linear system
// is written in nodal dofs w (u = R w, see node_rotations.hpp) and reduced by the equations
// (equation_elimination.hpp); with neither, every function here is the identity.
#pragma once

#include <vector>

#include "equation_elimination.hpp"
#include "mechanism_check.hpp"
#include "node_rotations.hpp"
#include "step_conditions.hpp"
#include "stiffness_matrix.hpp"

namespace styk::solver_detail {

class ModelConstraints {
 public:
  // Throws InputError at the offending *TRANSFORM / *EQUATION / *TIE line (see the builders).
  // Cyclic symmetry ties become equations (cyclic_equations.hpp).
  static ModelConstraints build(const Model& model, const PreparedModel& prepared,
                                const ElementRegistry& registry);

  bool empty() const { return rotations_.empty() && equations_.empty(); }
  // The model has a cyclic symmetry tie (its equations are part of equations()).
  bool cyclic() const { return !cyclic_.empty(); }
  const NodeRotations& rotations() const { return rotations_; }
  const EquationElimination& equations() const { return equations_; }

  // Node pairs the stiffness pattern needs beyond the elements' (for the equation fill).
  std::vector<std::pair<int, int>> extra_node_couplings(const Model& model,
                                                        const PreparedModel& prepared) const {
    return equations_.extra_node_couplings(model, prepared);
  }

  // The assembled (global) K becomes the reduced P^T R^T K R P in place.
  void apply(StiffnessMatrix& K) const;

  // The dofs the linear solver treats as known: `prescribed` (sorted nodal dofs) plus the
  // eliminated dofs. Throws InputError when an eliminated dof is also prescribed.
  std::vector<int> known_dofs(const Model& model, const PreparedModel& prepared,
                              const std::vector<int>& prescribed) const;

  // External forces on the nodal dofs: pressures turned to the nodal systems plus the
  // concentrated loads (given in them).
  std::vector<double> nodal_forces(const Model& model, const PreparedModel& prepared,
                                   const StepConditions& conditions) const;
  // f + R^T g: adds forces `global` (e.g. the thermal load; may be empty) to nodal forces f.
  std::vector<double> plus_global(std::vector<double> f, std::vector<double> global) const;

  // The right-hand side of the reduced system from the nodal forces (P^T f).
  std::vector<double> reduced_forces(std::vector<double> nodal) const;

  // Global displacements from the solver's nodal solution (dependent dofs filled, rotated).
  void to_global_displacements(std::vector<double>& w) const;

  // The restraints on rigid motion: each prescribed dof and each equation.
  std::vector<Restraint> restraints(const Model& model, const PreparedModel& prepared,
                                    const std::vector<int>& prescribed) const;

  // Dofs whose constraint force RF reports: `prescribed` and every equation term, sorted.
  std::vector<int> reaction_dofs(const std::vector<int>& prescribed) const;

 private:
  NodeRotations rotations_;
  EquationElimination equations_;
  std::vector<Equation> cyclic_;  // the equations of the cyclic symmetry ties
};

}  // namespace styk::solver_detail
