// *DLOAD GRAV and CENTRIF: the nodal forces of body forces per unit mass, integral of
// N^T density a(x) dV over each loaded element (its standard rule).
#pragma once

#include <vector>

#include "element_states.hpp"
#include "prepared_model.hpp"
#include "step_conditions.hpp"

namespace styk::solver_detail {

// Global nodal forces of the step's body loads (empty when it has none). The density is that of
// the element's material in `states`; a loaded element whose material has no *DENSITY is an
// InputError at the load's line.
std::vector<double> assemble_body_loads(const Model& model, const PreparedModel& prepared,
                                        const ElementStates& states,
                                        const StepConditions& conditions);

}  // namespace styk::solver_detail
