// Shell warnings that depend on the thickness (shell_warnings.hpp, docs/solver.md "Warnings";
// SPEC §7.3 "where methods fail"):
// - shear locking of the 8-node serendipity shells, estimated from a law fitted to measurements:
//   the bending stiffens by 1 + f, f = C (h / t)^2 (h / L)^p, h the element size (longest edge
//   chord), t the thickness, L the extent of the section's elements (section_extent.hpp); the
//   deflection falls short by f / (1 + f), warned from 10 % (f >= 1/9), the limit
//   docs/stability.md counts as failing. The constants are fitted in shell_locking.cpp.
// - a Kirchhoff (thin) shell on a thick section: STRI3 has no transverse shear deflection.
#pragma once

#include <string>
#include <vector>

#include "prepared_model.hpp"

namespace styk::solver_detail {

std::vector<std::string> shell_locking_warnings(const Model& model, const PreparedModel& prepared);
std::vector<std::string> thick_kirchhoff_shell_warnings(const Model& model,
                                                        const PreparedModel& prepared);

// The longest distance between consecutive corners (edge chords) of shell element e.
double shell_element_size(const Model& model, int e);

}  // namespace styk::solver_detail
