// Cyclic symmetry (*TIE, CYCLIC SYMMETRY, docs/input.md) as constraint equations for the linear
// solver: a static load that repeats in every sector gives every sector the same displacement
// field turned by the sector angle, so each slave node moves as its master node turned back,
//   u_slave = Q^T u_master   (Q turns the slave side onto the master side),
// three equations per slave node, the slave's dofs eliminated. Written in nodal dofs
// (w = R^T u for a node with a *TRANSFORM): w_s = R_s^T Q^T R_m w_m; with cylindrical systems
// about the symmetry axis on both nodes this is w_s = w_m. A node on the axis is its own image:
// it moves along the axis only (its two components across the axis vanish).
#pragma once

#include <vector>

#include "node_rotations.hpp"
#include "prepared_model.hpp"
#include "styk/core/cyclic_symmetry.hpp"

namespace styk::solver_detail {

// One equation per eliminated dof: terms[0] is the dependent dof (coefficient 1). Equations of
// axis nodes may have a single term (the dof is zero). `where` is the *TIE line. Nodes that no
// element uses are skipped.
std::vector<Equation> cyclic_equations(const Model& model, const PreparedModel& prepared,
                                       const NodeRotations& rotations,
                                       const std::vector<ResolvedCyclicSymmetry>& ties);

}  // namespace styk::solver_detail
