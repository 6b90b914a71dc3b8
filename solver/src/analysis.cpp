// The analysis entry point: lowers ties, couplings, MPCs and pre-tension sections to equations,
// then hands the model to the driver of what it contains: steady scalar field steps
// (scalar_field_analysis.hpp), contact pairs (contact_analysis.hpp) or linear statics
// (linear_static_analysis.hpp).
#include "styk/solver/analysis.hpp"

#include <optional>

#include "constraint_lowering.hpp"
#include "contact_analysis.hpp"
#include "linear_static_analysis.hpp"
#include "scalar_field_analysis.hpp"
#include "scalar_field_model.hpp"
#include "unsupported_features.hpp"

namespace styk {

using namespace solver_detail;

Results run_static_analysis(const Model& model, const ElementRegistry& registry,
                            const SolveOptions& options, ProgressSink* progress,
                            AnalysisReport* report) {
  reject_unsupported_features(model);
  // Ties, couplings, MPCs and pre-tension sections: solved as equations on a lowered copy.
  if (std::vector<std::string> notes;
      std::optional<Model> lowered = lower_constraints(model, registry, &notes)) {
    Results results = run_static_analysis(*lowered, registry, options, progress, report);
    restrict_to_nodes(model.node_count(), results);
    for (const std::string& note : notes) {
      if (progress != nullptr) progress->warning(note);
      if (report != nullptr) report->warnings.push_back(note);
    }
    return results;
  }
  // Steady heat / electric potential: one scalar unknown per node (scalar_field_analysis.hpp).
  if (has_scalar_field_steps(model))
    return run_scalar_field_analysis(model, registry, options, progress, report);
  // Contact pairs make the analysis nonlinear: load increments and the active-set iteration.
  if (!model.contact_pairs.empty())
    return run_contact_analysis(model, registry, options, progress, report);
  return run_linear_static_analysis(model, registry, options, progress, report);
}

}  // namespace styk
