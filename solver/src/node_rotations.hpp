// *TRANSFORM: nodes whose boundary conditions, concentrated loads and equation terms are given in
// a local system. The solver works in "nodal" dofs w: for a transformed node w = R^T u (its local
// components), for every other node w = u; u = R w with R = [e1 e2 e3] (local axes as columns, in
// global components). Rotations (dofs 4..6) are vectors too and turn with the same R: a node with
// rotations has the block diagonal diag(R, R). The stiffness becomes R^T K R block by block, which
// keeps the node-graph pattern, so prescribed local dofs are eliminated like any other.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "prepared_model.hpp"
#include "stiffness_matrix.hpp"
#include "styk/core/local_axes.hpp"

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
  // Global direction of nodal dof `dof` (component d of its node, translation or rotation): the
  // (d mod 3)-th local axis, or the global axis.
  Eigen::Vector3d direction(int dof) const;
  // Whether `dof` is a rotation (component 3..5 of its node).
  bool rotational(int dof) const;

  // v_a <- R_a^T v_a (global -> nodal) and back, on the translations and rotations of each node.
  void to_local(std::vector<double>& v) const { turn(v, true); }
  void to_global(std::vector<double>& v) const { turn(v, false); }
  // K_ab <- R_a^T K_ab R_b for every block touching a transformed node (3x3 sub-blocks).
  void rotate_stiffness(StiffnessMatrix& K) const;

 private:
  void turn(std::vector<double>& v, bool to_local) const;
  int node_of(int dof) const;

  std::vector<int> dof_offset_;        // the dof layout (PreparedModel::dof_offset)
  std::vector<int> rotation_of_node_;  // per active node, -1 if not transformed
  std::vector<Eigen::Matrix3d> rotations_;
};

}  // namespace styk::solver_detail
