// Spurious zero-energy modes of a model's own reduced-integration shell mesh, with its supports.
// The flat 2x2 patch count (spurious_shell_modes) says whether a type *can* carry such modes;
// whether a model does depends on its mesh and supports: SPEC §7.3's S9R plates carry none once
// the simple supports and symmetry planes hold them (docs/stability.md, thin-plate), while a
// single S8R element held at three corners carries two. Small meshes are therefore assembled
// whole, their *BOUNDARY-fixed dofs removed, and the zero eigenvalues counted beyond the rigid
// motions the supports leave free. Larger meshes are not checked here: a mode the supports
// leave free makes the stiffness matrix singular, which the solvers refuse by name
// (cholmod_solver.cpp "first_tiny_pivot", gamg_solver.cpp).
#pragma once

#include "prepared_model.hpp"

namespace styk::solver_detail {

// Meshes of reduced-integration shells up to this many elements are checked whole.
inline constexpr int kWholeShellMeshLimit = 16;

// Zero-energy modes beyond the free rigid motions of the model's shell elements whose type and
// rule has spurious modes (as a single element or in the 2x2 patch), assembled alone with a unit
// material and a thickness of a tenth of their mean size (the count depends on the rule, the
// mesh and the supports, not on the section) and held by the model's *BOUNDARY conditions
// (outside any step and in the first step; nodes under *TRANSFORM count as free). -1 when there
// are no such elements or more than kWholeShellMeshLimit.
int supported_shell_mesh_modes(const Model& model, const PreparedModel& prepared);

}  // namespace styk::solver_detail
