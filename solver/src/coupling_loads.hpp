// *COUPLING with *DISTRIBUTING (CalculiX 2.20 semantics): the reference node is not connected to
// the structure; the forces (and, for the listed rotations 4..6, the moments) applied to it by
// *CLOAD are carried to the nodes of the coupling surface as a system of point loads with the
// same resultant force and moment. Each surface node takes the share w_i = A_i / A of its nodal
// area A_i of the force; the moment about the area centre (the applied moment plus the moment
// of the force applied at the reference node) is carried by forces w_i (e_k x r_i) / I_k about
// the principal axes e_k of the weighted node cloud (r_i: the node's offset from the centre
// projected off e_k, I_k = sum w_i |r_i|^2).
#pragma once

#include <map>
#include <vector>

#include <Eigen/Core>

#include "prepared_model.hpp"

namespace styk::solver_detail {

struct DistributingTransfer {
  int reference_node = 0;
  std::vector<int> dofs;                              // reference dofs distributed (1..6)
  std::vector<int> nodes;                             // surface nodes
  std::vector<Eigen::Matrix<double, 3, 6>> per_load;  // global force on node i per unit load
  SourceLoc where;
};

// One transfer per distributing coupling of the model.
std::vector<DistributingTransfer> distributing_transfers(const Model& model,
                                                         const PreparedModel& prepared);

// The global nodal forces (model node -> force) of the loads `reference_loads` (node, dof 1..6 ->
// value, in the coupling's axes) on distributing reference nodes. Throws InputError at `where` of
// a load on a dof the coupling does not distribute (a moment not listed under *DISTRIBUTING).
std::map<int, Eigen::Vector3d> distribute_reference_loads(
    const std::vector<DistributingTransfer>& transfers,
    const std::map<std::pair<int, int>, std::pair<double, SourceLoc>>& reference_loads);

}  // namespace styk::solver_detail
