// The shell part of the solver's warnings (model_warnings.hpp, docs/solver.md §1 "Warnings";
// SPEC §7.3 "where methods fail"):
// - shear locking: the fully integrated 8-node serendipity shell (S8, 3x3) stiffens as it gets
//   thin; warned when an element's size (its longest edge chord) over the thickness reaches 10.
//   Measured on SPEC Tab 7.1b's plate (tests/verification/spec_7_3_plates_test.cpp): 0.7 % too
//   stiff at size / t = 2.5, 8 % at 25, 87 % at 250. The message names the measured
//   slenderness and the remedies (S8R, the 9-node Lagrange S9 / S9R, more elements);
// - spurious zero-energy modes: a flat 2x2 patch of the type (unit squares, t = 0.1) has more
//   zero eigenvalues than its 6 rigid motions (S9R: 4, measured; the single S8R element's two do
//   not survive in a patch): the mesh may carry them where the supports do not restrain them,
//   which the solver then refuses as singular. Meshes of at most 16 elements whose type has
//   spurious modes as a single element (S8R: 2, S9R) are also assembled whole, free of supports,
//   and their own zero-energy modes counted: a single S8R element is warned of, which the 2x2
//   patch does not show.
#pragma once

#include <string>
#include <vector>

#include "prepared_model.hpp"

namespace styk::solver_detail {

std::vector<std::string> shell_warnings(const Model& model, const PreparedModel& prepared);

// Zero-energy modes beyond the rigid motions of a flat cells x cells patch of `element`
// integrated with `kind` (the single element with cells = 1); 0 for non-shells.
int spurious_shell_modes(const TElement& element, RuleKind kind, int cells = 2);

}  // namespace styk::solver_detail
