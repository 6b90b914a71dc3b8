#include "cyclic_equations.hpp"

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace styk::solver_detail {
namespace {

// Coefficients below this (relative to 1) are round-off of the rotation at multiples of 90 deg.
constexpr double kNegligible = 1e-13;

Eigen::Matrix3d axes_of(const NodeRotations& rotations, int active_node) {
  const Eigen::Matrix3d* R = rotations.of(active_node);
  return R != nullptr ? *R : Eigen::Matrix3d::Identity();
}

Eigen::Matrix3d to_eigen(const Matrix3& Q) {
  Eigen::Matrix3d M;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M(i, j) = Q[i][j];
  return M;
}

// w_s = M w_m for one slave node: dependent w_s,i with the master's terms.
void add_pair(const Model& model, const PreparedModel& prepared, const NodeRotations& rotations,
              const Eigen::Matrix3d& Q, const CyclicNodePair& pair, const SourceLoc& where,
              std::vector<Equation>& out) {
  const int s = prepared.active_of_node[pair.slave], m = prepared.active_of_node[pair.master];
  if (s < 0 && m < 0) return;
  if (s < 0 || m < 0)
    throw InputError(where, "cyclic *TIE: node " +
                                std::to_string(model.node_ids[s < 0 ? pair.slave : pair.master]) +
                                " belongs to no element, but its partner node " +
                                std::to_string(model.node_ids[s < 0 ? pair.master : pair.slave]) +
                                " does");
  const Eigen::Matrix3d M =
      axes_of(rotations, s).transpose() * Q.transpose() * axes_of(rotations, m);
  for (int i = 0; i < 3; ++i) {
    Equation e;
    e.where = where;
    e.terms.push_back({pair.slave, i + 1, 1.0});
    for (int j = 0; j < 3; ++j)
      if (std::abs(M(i, j)) > kNegligible) e.terms.push_back({pair.master, j + 1, -M(i, j)});
    out.push_back(std::move(e));
  }
}

// A node on the axis: the two components across the axis vanish, e . R w = 0 for e normal to it.
// Row-reduced with pivoting so that each equation eliminates its own dof.
void add_axis_node(const PreparedModel& prepared, const NodeRotations& rotations,
                   const Eigen::Vector3d& axis, int node, const SourceLoc& where,
                   std::vector<Equation>& out) {
  const int a = prepared.active_of_node[node];
  if (a < 0) return;
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  const Eigen::Matrix3d R = axes_of(rotations, a);
  Eigen::Matrix<double, 2, 3> C;
  C.row(0) = (R.transpose() * e1).transpose();
  C.row(1) = (R.transpose() * e2).transpose();
  bool used[3] = {false, false, false};
  int pivots[2] = {0, 0};
  for (int r = 0; r < 2; ++r) {
    int pivot = -1;
    for (int j = 0; j < 3; ++j)
      if (!used[j] && (pivot < 0 || std::abs(C(r, j)) > std::abs(C(r, pivot)))) pivot = j;
    C.row(r) /= C(r, pivot);
    for (int other = 0; other < 2; ++other)
      if (other != r) C.row(other) -= C(other, pivot) * C.row(r);
    used[pivot] = true;
    pivots[r] = pivot;
  }
  for (int r = 0; r < 2; ++r) {
    Equation e;
    e.where = where;
    e.terms.push_back({node, pivots[r] + 1, 1.0});
    for (int j = 0; j < 3; ++j)
      if (j != pivots[r] && std::abs(C(r, j)) > kNegligible)
        e.terms.push_back({node, j + 1, C(r, j)});
    out.push_back(std::move(e));
  }
}

}  // namespace

std::vector<Equation> cyclic_equations(const Model& model, const PreparedModel& prepared,
                                       const NodeRotations& rotations,
                                       const std::vector<ResolvedCyclicSymmetry>& ties) {
  std::vector<Equation> out;
  for (const ResolvedCyclicSymmetry& tie : ties) {
    const Eigen::Matrix3d Q = to_eigen(tie.rotation);
    const SourceLoc& where = tie.definition->where;
    for (const CyclicNodePair& pair : tie.pairs)
      add_pair(model, prepared, rotations, Q, pair, where, out);
    const Eigen::Vector3d axis(tie.axis[0], tie.axis[1], tie.axis[2]);
    for (int node : tie.axis_nodes) add_axis_node(prepared, rotations, axis, node, where, out);
  }
  return out;
}

}  // namespace styk::solver_detail
