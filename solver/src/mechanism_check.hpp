// Rigid-body check before factorising: every connected part of the mesh must be held against the
// six rigid-body motions by its prescribed dofs. Catches the common input mistakes (a part with
// no support in some direction, or supported only on one node / one line so it can spin) with a
// message in words instead of a singular factorisation.
#pragma once

#include <vector>

#include "prepared_model.hpp"
#include "stiffness_matrix.hpp"

namespace styk::solver_detail {

// Throws InputError(SourceLoc{model.source, 0}, ...) naming the free motion and up to ten nodes
// of the part that can perform it. `prescribed` holds sorted active dof indices.
void check_rigid_body_modes(const Model& model, const PreparedModel& prepared,
                            const NodeGraph& graph, const std::vector<int>& prescribed);

}  // namespace styk::solver_detail
