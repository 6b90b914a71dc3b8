// Where a model is solvable but its answer is likely poor, said before solving (the user asked for
// failures to be reported, not answered with garbage; docs/solver.md §1 "Warnings"):
// - an element type with zero-energy (hourglass) modes that a mesh does not suppress: a patch of
//   its reference elements (zero_energy_modes.hpp) has more than the rigid-body modes (C3D8R0;
//   not C3D20R, whose single-element modes do not spread);
// - volumetric locking: nu at or above the type's measured onset (C3D8 0.45; C3D8R, C3D14,
//   C3D20, C3D27, C3D21 0.495; C3D28 0.49995; never C3D8I, C3D20R; other types: 0.45 if fully
//   integrated, i.e. more points in the full rule than in the reduced one and no incompatible
//   modes, or a linear tetrahedron) on a material that is not plane stress, without
//   TECHNIQUE=SELECTIVE (which a one-point rule cannot use);
// - linear tetrahedra (C3D4) in a part with fewer than 4 element sizes through its thinnest
//   extent: far too stiff in bending;
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

}  // namespace styk::solver_detail
