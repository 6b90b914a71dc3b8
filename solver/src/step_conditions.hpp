// What each analysis step sees: the boundary conditions and loads accumulated over the steps up to
// it (OP=MOD semantics, OP=NEW resets), translated to active dofs and validated against the mesh.
#pragma once

#include <vector>

#include "prepared_model.hpp"

namespace styk::solver_detail {

struct DofValue {
  int dof = 0;  // active dof index
  double value = 0.0;
};

struct StepConditions {
  std::vector<DofValue> prescribed;  // sorted by dof, one entry per dof
  // The prescribed dofs of *BOUNDARY, FIXED (sorted): their value is the displacement the
  // previous step ended with (nodal system), filled in by the step driver (0 in the first step).
  std::vector<int> fixed;
  std::vector<DofValue> nodal_loads;       // sorted by dof, one entry per dof
  std::vector<DistributedLoad> pressures;  // one per (element, face); face 1-based as given
  // *DLOAD GRAV / CENTRIF: one gravity load per (element, direction), one centrifugal load per
  // element (a later one replaces an earlier one, as in CalculiX).
  std::vector<BodyLoad> body_loads;
};

// One entry per Model::steps[k]. Throws InputError at the line of a boundary condition or load
// on a node no element uses, on a dof other than 1..3, or on a face the element does not have.
// Inactive dofs (no element stiffens them: uz of plane-element nodes) are prescribed to zero in
// every step, so the linear solver eliminates them; a load or a nonzero boundary value on one is
// an InputError at its line, a zero boundary value is accepted.
std::vector<StepConditions> accumulate_step_conditions(const Model& model,
                                                       const PreparedModel& prepared);

// The prescribed dof indices of `conditions`, sorted (to compare steps).
std::vector<int> prescribed_dofs(const StepConditions& conditions);

}  // namespace styk::solver_detail
