// Where a model is solvable but its answer is likely poor, said before solving (the user asked for
// failures to be reported, not answered with garbage; docs/solver.md §1 "Warnings"):
// - an element type with zero-energy (hourglass) modes that a mesh does not suppress: a 2 x 2 x 2
//   patch of reference elements has more than the 6 rigid-body modes (C3D8R0; not C3D20R, whose
//   single-element modes do not spread);
// - volumetric locking: nu >= 0.45 on a fully integrated element (its full rule has more points
//   than its reduced one, no incompatible modes) that is not plane stress, without
//   TECHNIQUE=SELECTIVE;
// - distorted elements: det J at the integration points varies by more than a factor 10 within
//   the element (min/max < 0.1), the worst named;
// - beams (beam_warnings.hpp): shear locking of slender fully integrated beams, with the measured
//   slenderness and the remedy, and spurious zero-energy modes of their integration rule.
#pragma once

#include <string>
#include <vector>

#include "prepared_model.hpp"

namespace styk::solver_detail {

// One sentence per problem, naming the elements, the section or the type and what to do.
std::vector<std::string> model_warnings(const Model& model, const PreparedModel& prepared);

// Zero-energy modes beyond the 6 rigid-body motions of a 2 x 2 x 2 patch of `element` (3D solids
// on the [-1, 1]^3 cube; 0 for other elements).
int spurious_zero_energy_modes(const TElement& element);

}  // namespace styk::solver_detail
