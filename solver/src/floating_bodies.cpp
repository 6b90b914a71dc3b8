#include "floating_bodies.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/QR>

namespace styk::solver_detail {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

std::vector<std::vector<int>> connected_parts(const NodeGraph& graph) {
  std::vector<int> part(graph.nodes(), -1);
  std::vector<std::vector<int>> parts;
  std::vector<int> stack;
  for (int seed = 0; seed < graph.nodes(); ++seed) {
    if (part[seed] >= 0) continue;
    const int label = static_cast<int>(parts.size());
    parts.emplace_back();
    part[seed] = label;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int a = stack.back();
      stack.pop_back();
      parts.back().push_back(a);
      for (std::int64_t p = graph.ptr[a]; p < graph.ptr[a + 1]; ++p)
        if (part[graph.adj[p]] < 0) {
          part[graph.adj[p]] = label;
          stack.push_back(graph.adj[p]);
        }
    }
    std::sort(parts.back().begin(), parts.back().end());
  }
  return parts;
}

// Rigid-body mode `mode` = (translation, rotation) evaluated at scaled position p.
Eigen::Vector3d rigid_motion(const Vector6& mode, const Eigen::Vector3d& p) {
  return mode.head<3>() + mode.tail<3>().cross(p);
}

}  // namespace

FloatingBodies find_floating_bodies(const Model& model, const PreparedModel& prepared,
                                    const NodeGraph& graph, const std::vector<int>& prescribed,
                                    const std::vector<char>& touches_contact) {
  std::vector<char> is_prescribed(prepared.active_dofs(), 0);
  for (int dof : prescribed) is_prescribed[dof] = 1;
  std::vector<Eigen::VectorXd> columns;
  std::vector<int> fixing;

  for (const std::vector<int>& part : connected_parts(graph)) {
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

    // G = sum over prescribed dofs of r r^T, r = the six rigid modes at that dof; its null space
    // is the set of rigid motions the supports leave free (as in the mechanism check).
    Matrix6 G = Matrix6::Zero();
    for (std::size_t i = 0; i < part.size(); ++i)
      for (int d = 0; d < 3; ++d) {
        if (!is_prescribed[3 * part[i] + d]) continue;
        Vector6 r = Vector6::Zero();
        r[d] = 1.0;
        for (int k = 0; k < 3; ++k) r[3 + k] = Eigen::Vector3d::Unit(k).cross(x[i])[d];
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

    const int n = static_cast<int>(part.size());
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * n, static_cast<int>(free_modes.size()));
    for (std::size_t k = 0; k < free_modes.size(); ++k)
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d u = rigid_motion(free_modes[k], x[i]);
        for (int d = 0; d < 3; ++d)
          if (!is_prescribed[3 * part[i] + d]) R(3 * i + d, static_cast<int>(k)) = u[d];
      }
    // The dofs that pin the free modes best: the first pivots of a column-pivoted QR of R^T.
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(R.transpose());
    for (std::size_t k = 0; k < free_modes.size(); ++k) {
      const int local = qr.colsPermutation().indices()[static_cast<int>(k)];
      fixing.push_back(3 * part[local / 3] + local % 3);
    }
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
