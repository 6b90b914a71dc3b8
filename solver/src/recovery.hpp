// Stress recovery: strains and stresses at the integration points of every element (full rule),
// nodal displacements, and reactions RF = internal force - external load at the constrained dofs,
// the internal force integral B^T sigma being summed in the same pass (no second stiffness pass).
#pragma once

#include <vector>

#include "element_states.hpp"
#include "node_rotations.hpp"
#include "prepared_model.hpp"
#include "step_conditions.hpp"
#include "styk/core/results.hpp"

namespace styk::solver_detail {

struct RecoveryInput {
  // Nodal dofs (local for transformed nodes) whose constraint force RF reports, sorted: the
  // prescribed dofs and the dofs of *EQUATION terms. RF is zero in the other directions.
  const std::vector<int>& reaction_dofs;
  const std::vector<double>& u;  // displacements on all active dofs, global directions
  const std::vector<double>& f;  // external forces on the nodal dofs (as reaction_dofs)
  // The elements' material state (law, temperatures, initial stresses), or none: the materials
  // of their sections at the initial temperatures.
  const ElementStates* states = nullptr;
  const NodeRotations* rotations = nullptr;  // the nodal systems, or none (all global)
  // Also fill ENER, element_volume and element_energy (energies) and THE (thermal strains).
  bool energies = false;
  bool thermal_strains = false;
};

// Fills U, RF (both global components), UR and RM (models with rotations), ip_offset, S and E,
// and station_offset, SF and SM (models with structural elements) of `out`. The stress is
// D (eps - eps_th) + sigma0 with the states' thermal strain and initial stress; E stays the total
// strain.
void recover_increment(const Model& model, const PreparedModel& prepared,
                       const RecoveryInput& input, int threads, IncrementResult& out);

// No thermal load, no local systems: RF at the `prescribed` active dofs.
void recover_increment(const Model& model, const PreparedModel& prepared,
                       const std::vector<int>& prescribed, const std::vector<double>& u,
                       const std::vector<double>& f, int threads, IncrementResult& out);

}  // namespace styk::solver_detail
