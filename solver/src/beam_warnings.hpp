// The beam part of the solver's warnings (model_warnings.hpp, docs/solver.md §1 "Warnings"; SPEC
// §7.3 "where methods fail"):
// - shear locking: a fully integrated beam (INTEGRATION=FULL) stiffens its bending by the factor
//   1 + L, L = k G A l^2 / (12 E I), for 2-node elements (exactly: a cantilever of n of them
//   deflects w_b (1 - 1 / (4 n^2)) / (1 + L) + P L / (k G A), tests/verification), and the part of
//   the bending that varies within an element by 1 + L, L = k G A l^2 / (60 E I), for 3-node ones
//   (the parasitic shear energy of the linear, resp. quadratic, part of the rotation field that
//   the element's displacement cannot match); the deflection falls short by L / (1 + L) for
//   2-node elements and, fully locked, by about (l / extent)^2 / 3 of that for 3-node ones
//   (beam_warnings.cpp); warned from an estimated 10 %, naming the measured slenderness l / h
//   and the remedies;
// - spurious zero-energy modes: a straight 2-element patch of the type with its section's rule
//   has more zero eigenvalues than the rigid motions (6 in space, 3 for planar beams).
#pragma once

#include <string>
#include <vector>

#include "prepared_model.hpp"

namespace styk::solver_detail {

std::vector<std::string> beam_warnings(const Model& model, const PreparedModel& prepared);

// Zero-energy modes beyond the rigid motions of a straight patch of two `element`s (unit length,
// unit square section) integrated with `kind`, over the dofs the type stiffens; 0 for non-beams.
int spurious_beam_modes(const TElement& element, RuleKind kind);

// The shear-locking factor L of beam element e (above), its slenderness l / h (length over the
// section depth in the plane where L is largest), its length over the extent of its section's
// elements (section_extent.hpp) and the estimated share of the deflection the locking costs.
struct BeamLocking {
  double factor = 0.0;
  double slenderness = 0.0;
  double share_of_member = 1.0;
  double error = 0.0;
};
BeamLocking beam_locking(const Model& model, const PreparedModel& prepared, int e,
                         double member_extent);

}  // namespace styk::solver_detail
