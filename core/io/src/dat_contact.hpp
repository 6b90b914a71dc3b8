// The *CONTACT PRINT blocks of the .dat report (docs/results.md, "Contact output").
#pragma once

#include <ostream>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::io {

// Prints the variables of `request` (CSTR, CDIS, CSTATUS) for every constrained slave node, then
// the total force and moment per pair and the equilibrium check. Throws InputError at the
// request's line for another variable.
void print_contact(std::ostream& out, const Model& model, const OutputRequest& request,
                   const IncrementResult& inc);

}  // namespace styk::io
