// The linear static step driver: one solve per step with the stiffness of the step's material
// state, CHOLMOD or CG + GAMG (chosen by size), distributed over MPI ranks when asked.
#pragma once

#include "styk/solver/analysis.hpp"

namespace styk::solver_detail {

// Throws InputError for a model that cannot be analysed (after the caller's lowering of ties,
// couplings, MPCs and pre-tension sections).
Results run_linear_static_analysis(const Model& model, const ElementRegistry& registry,
                                   const SolveOptions& options, ProgressSink* progress,
                                   AnalysisReport* report);

}  // namespace styk::solver_detail
