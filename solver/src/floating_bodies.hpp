// Bodies held only by contact: connected parts of the mesh whose restraints (prescribed dofs,
// *EQUATIONs) leave rigid-body motions free (a punch resting on a foundation, the upper of two
// stacked blocks). The contact driver factorises K with a few extra "fixing" dofs that pin exactly
// those motions (statically determinate, so a self-equilibrated load gives them no reaction) and
// carries the motions as unknowns of the contact system (contact::LinearContactSystem::G), with
// the parts' equilibrium as extra equations. Parts without contact nodes are left to the ordinary
// mechanism check.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "mechanism_check.hpp"
#include "node_rotations.hpp"
#include "prepared_model.hpp"
#include "stiffness_matrix.hpp"
#include "styk/contact/active_set.hpp"

namespace styk::solver_detail {

struct FloatingBodies {
  Eigen::MatrixXd modes;         // active_dofs x k: free rigid motions (global components)
  std::vector<int> fixing_dofs;  // k nodal active dofs pinning them, sorted
  int count() const { return static_cast<int>(modes.cols()); }
};

// `given`: every prescribed dof and equation (ModelConstraints::restraints); `known`: the
// nodal dofs the linear solver eliminates (prescribed and *EQUATION-dependent), sorted; the modes
// are zero in the prescribed nodal directions and the fixing dofs are chosen among the others.
// `rotations` gives the nodal systems of *TRANSFORM nodes. `touches_contact` flags active nodes
// that belong to a contact constraint.
FloatingBodies find_floating_bodies(const Model& model, const PreparedModel& prepared,
                                    const NodeGraph& graph, const std::vector<Restraint>& given,
                                    const std::vector<int>& prescribed,
                                    const std::vector<int>& known, const NodeRotations& rotations,
                                    const std::vector<char>& touches_contact);

// The report of a body held only by contact that slides (contact::EquilibriumLoss found by the
// active set): its free motion R v fitted as a translation or a rotation (axis and a point on it),
// the load along it and the friction capacity as a force or a moment about the axis, the number
// of slipping contact nodes and a node of the body.
std::string sliding_report(const Model& model, const PreparedModel& prepared,
                           const FloatingBodies& floating, const contact::EquilibriumLoss& loss);

}  // namespace styk::solver_detail
