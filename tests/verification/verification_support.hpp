// Shared helpers of the SPEC verification tests: solve a model in-process, read nodal values,
// grade an error the thesis' way (SPEC §3.1, Tab 3.12).
#pragma once

#include <string>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::verification {

// Solves `model` with the built-in elements; throws what the solver throws.
Results solve(const Model& model);

// Mean of displacement component `dof` (0 = x) over the nodes of node set `set` in the last
// increment.
double mean_displacement(const Model& model, const Results& results, const std::string& set,
                         int dof);

// SPEC §3.1 Tab 3.12: A < 2 %, B < 10 %, C < 20 %, D < 50 %, E otherwise (relative error).
char grade(double value, double reference);

}  // namespace styk::verification
