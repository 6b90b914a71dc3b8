#include "floating_bodies.hpp"

#include "mechanism_check.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/QR>

namespace styk::solver_detail {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// Rigid-body mode `mode` = (translation, rotation) evaluated at scaled position p.
Eigen::Vector3d rigid_motion(const Vector6& mode, const Eigen::Vector3d& p) {
  return mode.head<3>() + mode.tail<3>().cross(p);
}

}  // namespace

FloatingBodies find_floating_bodies(const Model& model, const PreparedModel& prepared,
                                    const NodeGraph& graph,
                                    const std::vector<Restraint>& restraints,
                                    const std::vector<int>& prescribed,
                                    const std::vector<int>& known, const NodeRotations& rotations,
                                    const std::vector<char>& touches_contact) {
  std::vector<char> is_prescribed(prepared.active_dofs(), 0), is_known(prepared.active_dofs(), 0);
  for (int dof : prescribed) is_prescribed[dof] = 1;
  for (int dof : known) is_known[dof] = 1;
  std::vector<Eigen::VectorXd> columns;
  std::vector<int> fixing;
  const std::vector<std::vector<int>> parts = connected_parts(graph);
  std::vector<int> part_of(prepared.active_nodes(), -1), index_in_part(prepared.active_nodes(), -1);
  for (std::size_t k = 0; k < parts.size(); ++k)
    for (std::size_t i = 0; i < parts[k].size(); ++i) {
      part_of[parts[k][i]] = static_cast<int>(k);
      index_in_part[parts[k][i]] = static_cast<int>(i);
    }
  std::vector<std::vector<const Restraint*>> restraints_of(parts.size());
  for (const Restraint& r : restraints)
    if (!r.terms.empty()) restraints_of[part_of[r.terms.front().first]].push_back(&r);

  for (std::size_t k_part = 0; k_part < parts.size(); ++k_part) {
    const std::vector<int>& part = parts[k_part];
    if (std::none_of(part.begin(), part.end(), [&](int a) { return touches_contact[a] != 0; }))
      continue;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> x(part.size());
    for (std::size_t i = 0; i < part.size(); ++i) {
      const Vec3& c = model.coords[prepared.node_of_active[part[i]]];
      x[i] = Eigen::Vector3d(c[0], c[1], c[2]);
      lo = lo.cwiseMin(x[i]);
      hi = hi.cwiseMax(x[i]);
      centroid += x[i];
    }
    centroid /= static_cast<double>(part.size());
    const double size = std::max((hi - lo).maxCoeff(), 1e-300);
    for (Eigen::Vector3d& p : x) p = (p - centroid) / size;

    // G = sum over the restraints of r r^T, r = the restraint applied to the six rigid modes
    // (a term v at x sees translation t and rotation w as v.t + w.(x cross v)); its null space is
    // the set of rigid motions the restraints leave free (as in the mechanism check).
    Matrix6 G = Matrix6::Zero();
    for (const Restraint* restraint : restraints_of[k_part]) {
      Vector6 r = Vector6::Zero();
      for (const auto& [a, v] : restraint->terms) {
        r.head<3>() += v;
        r.tail<3>() += x[index_in_part[a]].cross(v);
      }
      G.noalias() += r * r.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(G);
    const double largest = eigen.eigenvalues()[5];
    std::vector<Vector6> free_modes;
    for (int k = 0; k < 6; ++k)
      if (!(largest > 0.0) || eigen.eigenvalues()[k] <= 1e-12 * largest) {
        Vector6 mode = eigen.eigenvectors().col(k);
        for (int c = 0; c < 6; ++c)
          if (std::abs(mode[c]) < 1e-10) mode[c] = 0.0;  // round-off of an exact mode
        free_modes.push_back(mode.normalized());
      }
    if (free_modes.empty()) continue;

    // The modes in nodal components (local for *TRANSFORM nodes): zero in the prescribed
    // directions (round-off of an exact null vector), candidates for pinning in the free ones.
    const int n = static_cast<int>(part.size());
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(3 * n, static_cast<int>(free_modes.size()));
    for (std::size_t k = 0; k < free_modes.size(); ++k)
      for (int i = 0; i < n; ++i) {
        Eigen::Vector3d u = rigid_motion(free_modes[k], x[i]);
        const Eigen::Matrix3d* axes = rotations.of(part[i]);
        if (axes != nullptr) u = axes->transpose() * u;
        for (int d = 0; d < 3; ++d)
          if (!is_prescribed[3 * part[i] + d]) W(3 * i + d, static_cast<int>(k)) = u[d];
      }
    // The dofs that pin the free modes best: the first pivots of a column-pivoted QR of W^T over
    // the dofs the solver keeps (not prescribed, not eliminated by an equation).
    Eigen::MatrixXd candidates = W;
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d)
        if (is_known[3 * part[i] + d]) candidates.row(3 * i + d).setZero();
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(candidates.transpose());
    for (std::size_t k = 0; k < free_modes.size(); ++k) {
      const int local = qr.colsPermutation().indices()[static_cast<int>(k)];
      fixing.push_back(3 * part[local / 3] + local % 3);
    }
    Eigen::MatrixXd R = W;  // back to global components
    for (int i = 0; i < n; ++i)
      if (const Eigen::Matrix3d* axes = rotations.of(part[i]))
        for (int k = 0; k < R.cols(); ++k)
          R.block<3, 1>(3 * i, k) = *axes * W.block<3, 1>(3 * i, k);
    for (int k = 0; k < R.cols(); ++k) {
      Eigen::VectorXd column = Eigen::VectorXd::Zero(prepared.active_dofs());
      for (int i = 0; i < n; ++i) column.segment<3>(3 * part[i]) = R.block<3, 1>(3 * i, k);
      columns.push_back(std::move(column));
    }
  }

  FloatingBodies out;
  out.modes.resize(prepared.active_dofs(), static_cast<int>(columns.size()));
  for (std::size_t k = 0; k < columns.size(); ++k) out.modes.col(static_cast<int>(k)) = columns[k];
  std::sort(fixing.begin(), fixing.end());
  out.fixing_dofs = fixing;
  return out;
}

}  // namespace styk::solver_detail
