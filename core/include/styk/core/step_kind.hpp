// What a step's kind is called in a deck and which dof it solves for: one table for the reader,
// the writer and the solver's messages.
#pragma once

#include "styk/core/model.hpp"

namespace styk {

// "*STATIC", "*HEAT TRANSFER" or "*COUPLED THERMAL-ELECTRICAL".
const char* procedure_keyword(StepKind kind);
// The dof a scalar step solves for: 11 temperature, 9 electric potential; 0 for static steps.
int scalar_dof(StepKind kind);

}  // namespace styk
