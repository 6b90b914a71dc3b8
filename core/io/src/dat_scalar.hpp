// The scalar-field blocks of the .dat report (docs/results.md, "The .dat report"): NT / EPOT and
// RFL / RECUR per node, HFL / ECD per integration point, in CalculiX's layout for heat.
#pragma once

#include <ostream>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::io {

// Prints the variables of a *NODE PRINT or *EL PRINT request of a scalar-field increment. Throws
// InputError at the request's line for a variable of another procedure, std::runtime_error when
// the increment lacks the field.
void print_scalar(std::ostream& out, const Model& model, const OutputRequest& request,
                  const IncrementResult& inc);

}  // namespace styk::io
