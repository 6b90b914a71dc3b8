// Model features the reader accepts but this solver cannot act on yet. Checked first so a deck
// using them is refused by name and line instead of being solved as if they were absent.
#pragma once

#include "styk/core/model.hpp"

namespace styk::solver_detail {

// Throws InputError at the first *EQUATION, *TRANSFORM or step *TEMPERATURE of a model with
// contact pairs (the contact path does not apply them yet). Each check goes when the solver
// learns the feature.
void reject_unsupported_features(const Model& model);

}  // namespace styk::solver_detail
