// Thermal loading of a linear static step: the nodal temperature change of each step and the
// equivalent nodal forces of the thermal strain.
//
// Semantics (CalculiX/Abaqus *EXPANSION with a constant coefficient): the thermal strain is
// alpha (T - T_ref) - alpha (T_initial - T_ref) = alpha (T - T_initial), so the body is strain-free
// at its initial temperature and the reference temperature ZERO= cancels out.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "prepared_model.hpp"

namespace styk::solver_detail {

// Per Model::steps[k]: dT = T_step - T_initial at every model node (node index), or an empty
// vector when the step's temperature equals the initial one everywhere (no thermal load).
// T_initial comes from *INITIAL CONDITIONS, TYPE=TEMPERATURE (0 where not given); T_step is
// T_initial overridden by the *TEMPERATURE data of the steps up to k, OP=NEW resetting to
// T_initial first and a later value for a node overriding an earlier one.
std::vector<std::vector<double>> step_temperature_changes(const Model& model);

// Equivalent nodal forces of the thermal strain, integral of B^T D alpha dT dV, on all active
// dofs (global directions). `nodal_dT` is indexed by model node. Throws InputError at an
// element's line when its material has no *EXPANSION but its nodes see a temperature change.
std::vector<double> assemble_thermal_load(const Model& model, const PreparedModel& prepared,
                                          const std::vector<double>& nodal_dT, int threads);

// The temperature changes of element e's nodes (dT_e, node order of the element).
void element_temperature_changes(const Model& model, int e, const std::vector<double>& nodal_dT,
                                 Eigen::VectorXd& dT_e);

}  // namespace styk::solver_detail
