#include "analysis_setup.hpp"

#include <string>

#include "model_warnings.hpp"
#include "parallel.hpp"

namespace styk::solver_detail {
namespace {

AnalysisReport* cleared(AnalysisReport* report) {
  if (report != nullptr) *report = AnalysisReport{};
  return report;
}

}  // namespace

AnalysisStart::AnalysisStart(const SolveOptions& options, ProgressSink* progress,
                             AnalysisReport* report)
    : phases_(progress, cleared(report)), threads_(resolve_threads(options.threads)) {}

MechanicalModel prepare_mechanical_model(const Model& model, const ElementRegistry& registry,
                                         const PhaseRecorder& phases) {
  const SourceLoc whole_model{model.source, 0};
  if (model.steps.empty())
    throw InputError(whole_model, "the model has no *STEP: there is nothing to analyse");
  if (model.element_count() == 0) throw InputError(whole_model, "the model has no elements");
  MechanicalModel out;
  out.prepared = prepare_model(model, registry);
  check_output_requests(model, out.prepared);
  out.conditions = accumulate_step_conditions(model, out.prepared);
  out.kinematic = ModelConstraints::build(model, out.prepared, registry);
  for (const std::string& warning : model_warnings(model, out.prepared)) phases.warning(warning);
  return out;
}

}  // namespace styk::solver_detail
