// Which output requests a step has in effect, with CalculiX's rules: the first request of a kind
// (*NODE PRINT, *EL PRINT, ...) in a step replaces the requests of that kind of the steps before;
// a step with none of a kind repeats them. FREQUENCY= given on any request holds for every kind
// from its step on until another one is given: increments n, 2n, ... and the last increment of each
// step are output (n = 0: none).
#pragma once

#include <vector>

#include "styk/core/model.hpp"

namespace styk {

// The requests of `kind` in effect in step `step` (0-based), in deck order.
std::vector<const OutputRequest*> effective_requests(const Model& model, std::size_t step,
                                                     OutputRequest::Kind kind);

// The requests of every kind in effect in step `step`, in deck order (a kind carried over from an
// earlier step keeps its place by that step).
std::vector<const OutputRequest*> effective_outputs(const Model& model, std::size_t step);

// The FREQUENCY in effect in step `step` (1 unless a request of this or an earlier step says).
int output_frequency(const Model& model, std::size_t step);

// Whether increment `increment` (1-based) of step `step` is output; `last` when it ends the step.
bool output_due(const Model& model, std::size_t step, int increment, bool last);

}  // namespace styk
