// Where a model is solvable but its answer is likely poor, said before solving (the user asked for
// failures to be reported, not answered with garbage; docs/solver.md §1 "Warnings"):
// - an element type with zero-energy (hourglass) modes that a mesh does not suppress: a patch of
//   its reference elements (zero_energy_modes.hpp) has more than the rigid-body modes (C3D8R0;
//   not C3D20R, whose single-element modes do not spread);
// - volumetric locking: nu >= 0.45 on a fully integrated element (its full rule has more points
//   than its reduced one, no incompatible modes) or a linear tetrahedron, not plane stress,
//   without TECHNIQUE=SELECTIVE (which cannot help a linear tetrahedron);
// - linear tetrahedra (C3D4) in a part with fewer than 4 element sizes through its thinnest
//   extent: far too stiff in bending;
// - distorted elements: det J at the integration points varies by more than a factor 10 within
//   the element (min/max < 0.1), the worst named.
#pragma once

#include <string>
#include <vector>

#include "prepared_model.hpp"

namespace styk::solver_detail {

// One sentence per problem, naming the elements, the section or the type and what to do.
std::vector<std::string> model_warnings(const Model& model, const PreparedModel& prepared);

}  // namespace styk::solver_detail
