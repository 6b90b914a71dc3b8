// Thermal loading of a linear static step: the nodal temperature change of each step and the
// equivalent nodal forces of the thermal strain.
//
// Semantics (CalculiX/Abaqus *EXPANSION with a constant coefficient): the thermal strain is
// alpha (T - T_ref) - alpha (T_initial - T_ref) = alpha (T - T_initial), so the body is strain-free
// at its initial temperature and the reference temperature ZERO= cancels out.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "element_states.hpp"
#include "prepared_model.hpp"

namespace styk::solver_detail {

// Per Model::steps[k]: dT = T_step - T_initial at every model node (node index), or an empty
// vector when the step's temperature equals the initial one everywhere (no thermal load).
// T_initial comes from *INITIAL CONDITIONS, TYPE=TEMPERATURE (0 where not given); T_step is
// T_initial overridden by the *TEMPERATURE data of the steps up to k, OP=NEW resetting to
// T_initial first and a later value for a node overriding an earlier one.
std::vector<std::vector<double>> step_temperature_changes(const Model& model);

// Per Model::steps[k]: the absolute temperature T_step per model node, or an empty vector when it
// equals the initial temperature everywhere (the changes above added to the initial values).
std::vector<std::vector<double>> step_temperatures(const Model& model);

// Equivalent nodal forces of the eigenstrains (thermal strain and initial stresses) of the
// elements `states` says are loaded, integral of B^T (D eps_th - sigma0) dV, on all active dofs
// (global directions). Throws InputError at a material without *EXPANSION whose elements see a
// temperature change.
std::vector<double> assemble_eigenstrain_load(const Model& model, const PreparedModel& prepared,
                                              const ElementStates& states, int threads);

}  // namespace styk::solver_detail
