// Model features the reader accepts but this solver cannot act on yet. Checked first so a deck
// using them is refused by name and line instead of being solved as if they were absent.
#pragma once

#include "styk/core/model.hpp"

namespace styk::solver_detail {

// Throws InputError at the first feature the model uses that the solver cannot apply. Currently
// none: *EQUATION, *TRANSFORM and *TEMPERATURE work with and without contact pairs. A check is
// added here when the reader learns a keyword before the solver does.
void reject_unsupported_features(const Model& model);

}  // namespace styk::solver_detail
