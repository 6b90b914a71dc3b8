// *PRESSURE PENETRATION across the steps (history data, like loads): which definitions act in
// each step and the fluid pressure they ramp between, and the per-increment summary with the leak
// check (docs/contact.md, "Pressure penetration").
#pragma once

#include <string>
#include <vector>

#include "styk/contact/penetration.hpp"
#include "styk/core/results.hpp"

namespace styk::solver_detail {

struct StepPenetration {
  std::vector<const PressurePenetration*> definitions;  // acting in the step
  std::vector<double> start, end;  // fluid pressure at the step's start and end, per definition
  // The fluid pressures at step fraction tau (linear ramp, as loads).
  std::vector<double> at(double tau) const;
};

// One entry per Model::steps[k]: a step keeps the previous step's definitions (OP=MOD), OP=NEW
// drops them; a definition for a pair already acting replaces it. The pressure ramps from the
// pair's value at the end of the previous step (0 when it did not act there).
std::vector<StepPenetration> accumulate_penetrations(const Model& model);

// The summary of every zone of `layout` at the converged `state` (IncrementResult::penetrations).
std::vector<PenetrationResult> penetration_results(const Model& model,
                                                   const contact::PenetrationLayout& layout,
                                                   const contact::ContactState& state,
                                                   const std::vector<double>& pressures);

}  // namespace styk::solver_detail
