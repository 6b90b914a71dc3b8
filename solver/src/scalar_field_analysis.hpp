// The steady scalar-field driver (docs/solver.md, "Steady heat and electric potential"):
// conductance assembly, Dirichlet elimination, CHOLMOD, nodal reaction flows, and the gradients and
// fluxes at the integration points with their nodal averages. run_static_analysis hands decks with
// *HEAT TRANSFER or *COUPLED THERMAL-ELECTRICAL steps to it.
#pragma once

#include "styk/solver/analysis.hpp"

namespace styk::solver_detail {

// Runs every step (all of one scalar kind) as a linear steady state, one increment each.
Results run_scalar_field_analysis(const Model& model, const ElementRegistry& registry,
                                  const SolveOptions& options, ProgressSink* progress,
                                  AnalysisReport* report);

}  // namespace styk::solver_detail
