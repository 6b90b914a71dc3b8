// The contact output of an increment (IncrementResult::contact, contact_pairs) from the converged
// state: pressure and shear tractions (force / nodal area), accumulated slip, gap, status, force,
// and per pair the total force and its moment about the origin.
#pragma once

#include <vector>

#include "styk/contact/active_set.hpp"
#include "styk/contact/constraints.hpp"
#include "styk/core/results.hpp"

namespace styk::contact {

void fill_contact_results(const Model& model, const std::vector<ContactConstraint>& constraints,
                          const ContactState& state, IncrementResult& out);

// The contact force on the slave node of constraint j (global axes); the master nodes carry
// -weight times it.
Eigen::Vector3d slave_force(const ContactConstraint& constraint, const ConstraintState& state);

}  // namespace styk::contact
