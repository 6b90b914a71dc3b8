// Rigid-body check before factorising: every connected part of the mesh must be held against the
// six rigid-body motions by its prescribed dofs. Catches the common input mistakes (a part with
// no support in some direction, or supported only on one node / one line so it can spin) with a
// message in words instead of a singular factorisation.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "prepared_model.hpp"
#include "stiffness_matrix.hpp"

namespace styk::solver_detail {

// Connected parts of the node graph (active node indices), each a list of its nodes.
std::vector<std::vector<int>> connected_parts(const NodeGraph& graph);

// Throws InputError(SourceLoc{model.source, 0}, ...) naming the free motion and up to ten nodes
// of the part that can perform it. `prescribed` holds sorted active dof indices. A rigid motion
// moves the rotations of nodes that have them (a beam spinning about its own axis is a
// mechanism).
void check_rigid_body_modes(const Model& model, const PreparedModel& prepared,
                            const NodeGraph& graph, const std::vector<int>& prescribed);

// A linear condition on displacements and rotations, sum_i v_i . u(a_i) (or v_i . rotation(a_i))
// fixed: a prescribed dof (one term, its direction) or an *EQUATION (coefficient times the
// direction of each term's dof).
struct RestraintTerm {
  int node = 0;            // active node
  Eigen::Vector3d vector;  // global
  bool rotation = false;   // acts on the node's rotation, not its displacement
};
struct Restraint {
  std::vector<RestraintTerm> terms;
};

// `restraints` and, for every node of an axisymmetric element, its radial direction (x): a ring
// cannot translate radially, its only rigid motion is the axial translation.
std::vector<Restraint> with_ring_restraints(const PreparedModel& prepared,
                                            std::vector<Restraint> restraints);

// The same check for general restraints (`given`). A part is a connected component of `graph`
// (which links the nodes of an equation), and a rigid motion of a part must violate some restraint.
// Parts linked by equations are checked as one body: a hinge between them is left to the
// factorisation's pivot check.
void check_rigid_body_modes(const Model& model, const PreparedModel& prepared,
                            const NodeGraph& graph, const std::vector<Restraint>& given);

}  // namespace styk::solver_detail
