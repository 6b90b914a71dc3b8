// What every analysis driver starts with (linear static, steady scalar field, contact): the
// report reset, the phase recorder and the thread count; and the "check" phase the mechanical
// drivers (linear static, contact) share.
#pragma once

#include <vector>

#include "model_constraints.hpp"
#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "step_conditions.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::solver_detail {

class AnalysisStart {
 public:
  // Clears `report` (may be null) for this analysis.
  AnalysisStart(const SolveOptions& options, ProgressSink* progress, AnalysisReport* report);

  const PhaseRecorder& phases() const { return phases_; }
  int threads() const { return threads_; }

 private:
  PhaseRecorder phases_;
  int threads_;
};

// A mechanical model ready for assembly: active dofs and formulation, the accumulated step
// conditions (loads, prescribed dofs) and the kinematic constraints (*TRANSFORM, *EQUATION).
struct MechanicalModel {
  PreparedModel prepared;
  std::vector<StepConditions> conditions;
  ModelConstraints kinematic;
};

// The shared part of the "check" phase (call it inside the caller's phase scope): a model with
// steps and elements (InputError otherwise), its output requests checked, the model warnings
// passed to `phases`.
MechanicalModel prepare_mechanical_model(const Model& model, const ElementRegistry& registry,
                                         const PhaseRecorder& phases);

}  // namespace styk::solver_detail
