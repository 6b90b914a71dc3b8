// What the contact driver reports about a converged increment: the equilibrium check, the pairs
// that reached full slip (their friction capacity), the iteration log line and the nodes named in
// a failure message.
#pragma once

#include <string>
#include <vector>

#include "prepared_model.hpp"
#include "styk/contact/active_set.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::solver_detail {

// The slave nodes' ids of `which` (constraint indices), at most 20 listed.
std::string node_ids(const Model& model, const std::vector<contact::ContactConstraint>& constraints,
                     const std::vector<int>& which);

// Applied loads + reactions and the contact forces on both sides, relative to the forces
// involved (docs/contact.md: < 1e-8 in every converged increment).
void check_equilibrium(const PreparedModel& prepared, const std::vector<double>& applied,
                       const IncrementResult& increment,
                       const std::vector<contact::ContactConstraint>& constraints,
                       const contact::ContactState& state, ContactEquilibrium& out);

// Per frictional pair: whether every closed slave node slips (full slip: the friction capacity
// is reached).
std::vector<char> full_slip(const Model& model,
                            const std::vector<contact::ContactConstraint>& constraints,
                            const contact::ContactState& state);

// The log line of a pair at full slip, with the contact forces' resultant, which is then the
// capacity (about the cyclic symmetry axis, per sector and for the whole structure, when the model
// has one).
std::string full_slip_report(const Model& model, const IncrementResult& increment, int pair);

// One iteration's progress line: statuses, changes, residual and what steered the step.
std::string iteration_line(const contact::IterationRecord& record, bool fluid);

}  // namespace styk::solver_detail
