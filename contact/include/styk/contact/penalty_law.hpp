// Penalty laws of *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE= (docs/contact.md, "Penalty laws"):
// instead of the exact constraint d_n = gap0 a closed node carries the force of a spring between
// the slave node and its master point, lambda_n = K A (d_n - gap0) (LINEAR: compression only;
// TIED: both signs and also tangentially, lambda_t = K A d_t, never opening). K is the law's slope
// (pressure per length) and A the node's contact area (SPEC §2.5), so the pressure is K times the
// overclosure. EXPONENTIAL (CalculiX's law): lambda_n = A p0 exp(-beta g), g = gap0 - d_n the
// clearance, beta = ln(100) / c0, while g <= c0; nothing beyond. The springs enter the active-set
// iteration as their compliance in series with the structure's, the exponential one linearised
// at the iterate (friction_law.hpp).
#pragma once

#include <string>

#include "styk/contact/constraints.hpp"
#include "styk/core/model.hpp"

namespace styk::contact {

// Throws InputError (at the *SURFACE BEHAVIOR line) for a combination the solver does not handle:
// TIED together with *FRICTION.
void check_penalty_law(const SurfaceInteraction& interaction);

// Sets penalty_stiffness / bonded (LINEAR, TIED) or exponential_force0 / exponential_beta
// (EXPONENTIAL) of a constraint of a pair with `interaction`. A node surface
// (TYPE=NODE) has no area: its "pressure" is a force (the Abaqus and CalculiX convention), A = 1.
// A face slave node with a non-positive area (the corner of a C3D20 face) would be a spring of
// negative stiffness: InputError naming the node.
void apply_penalty_law(const SurfaceInteraction& interaction, const Surface& slave_surface,
                       const std::string& node_label, ContactConstraint& constraint);

// "exact (hard)", "penalty LINEAR K=2e+06", "penalty TIED K=1e+05": how `styk solve` and the .dat
// name the law of a pair.
std::string normal_law_label(const PressureOverclosure& behavior);

}  // namespace styk::contact
