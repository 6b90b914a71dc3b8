// *TRANSFORM: nodes whose boundary conditions, concentrated loads and equation terms are given in
// a local system. The solver works in "nodal" dofs w: for a transformed node w = R^T u (its local
// components), for every other node w = u; u = R w with R = [e1 e2 e3] (local axes as columns, in
// global components). The stiffness becomes R^T K R block by block, which keeps the node-graph
// pattern, so prescribed local dofs are eliminated like any other.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "prepared_model.hpp"
#include "styk/core/local_axes.hpp"
#include "stiffness_matrix.hpp"

namespace styk::solver_detail {

class NodeRotations {
 public:
  // Throws InputError at a *TRANSFORM line whose node set does not exist, or whose cylindrical
  // axis passes through one of the set's nodes (the radial direction is undefined there). Nodes
  // of the set that no element uses are skipped (they have no dofs).
  static NodeRotations from_transforms(const Model& model, const PreparedModel& prepared);

  bool empty() const { return rotations_.empty(); }
  // Local axes (columns) of active node a; nullptr when the node is not transformed.
  const Eigen::Matrix3d* of(int active_node) const {
    const int r = rotation_of_node_.empty() ? -1 : rotation_of_node_[active_node];
    return r < 0 ? nullptr : &rotations_[r];
  }
  // Global direction of nodal dof `dof` (3a + d): the d-th local axis, or the global axis.
  Eigen::Vector3d direction(int dof) const;

  void to_local(std::vector<double>& v) const;   // v_a <- R_a^T v_a (global -> nodal)
  void to_global(std::vector<double>& v) const;  // v_a <- R_a v_a (nodal -> global)
  // K_ab <- R_a^T K_ab R_b for every block touching a transformed node.
  void rotate_stiffness(StiffnessMatrix& K) const;

 private:
  std::vector<int> rotation_of_node_;  // per active node, -1 if not transformed
  std::vector<Eigen::Matrix3d> rotations_;
};

}  // namespace styk::solver_detail
