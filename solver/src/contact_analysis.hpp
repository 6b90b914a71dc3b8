// The static step driver of models with contact pairs (docs/contact.md): load increments within
// each step (fixed with *STATIC, DIRECT; automatic with cut-backs otherwise), the contact state
// carried from increment to increment and step to step, one IncrementResult per converged
// increment. The linear algebra: one CHOLMOD factorisation of K per set of prescribed dofs, the
// contact compliance S = B K^-1 B^T from blocked solves, and the dense active-set iteration of
// styk_contact on top; displacements by one more solve per converged increment.
#pragma once

#include "styk/solver/analysis.hpp"

namespace styk::solver_detail {

// Throws InputError for a model that cannot be analysed, NotConvergedError (exit code 2) when an
// increment does not converge at the smallest allowed size, naming the step, the time, the
// reason and the nodes whose status kept changing.
Results run_contact_analysis(const Model& model, const ElementRegistry& registry,
                             const SolveOptions& options, ProgressSink* progress,
                             AnalysisReport* report);

}  // namespace styk::solver_detail
