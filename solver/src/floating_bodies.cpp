#include "floating_bodies.hpp"

#include "mechanism_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Cholesky>
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

// printf-style formatting of up to three numbers (the report's pieces).
std::string text(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

}  // namespace

FloatingBodies find_floating_bodies(const Model& model, const PreparedModel& prepared,
                                    const NodeGraph& graph, const std::vector<Restraint>& given,
                                    const std::vector<int>& prescribed,
                                    const std::vector<int>& known, const NodeRotations& rotations,
                                    const std::vector<char>& touches_contact) {
  const std::vector<Restraint> restraints = with_ring_restraints(prepared, given);
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
    if (!r.terms.empty()) restraints_of[part_of[r.terms.front().node]].push_back(&r);

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
      for (const RestraintTerm& term : restraint->terms) {
        if (term.rotation) {
          r.tail<3>() += term.vector;
          continue;
        }
        r.head<3>() += term.vector;
        r.tail<3>() += x[index_in_part[term.node]].cross(term.vector);
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
    // Rows: the part's dofs in order (a node's translations, then its rotations if it has them;
    // the rotation of mode (t, w) on the scaled coordinates is w / size).
    const int n = static_cast<int>(part.size());
    std::vector<int> row_dof;  // local row -> active dof
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < prepared.node_dofs(part[i]); ++c)
        row_dof.push_back(prepared.dof(part[i], c));
    const int rows = static_cast<int>(row_dof.size());
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(rows, static_cast<int>(free_modes.size()));
    for (std::size_t k = 0; k < free_modes.size(); ++k)
      for (int i = 0, row = 0; i < n; row += prepared.node_dofs(part[i]), ++i) {
        const Eigen::Matrix3d* axes = rotations.of(part[i]);
        for (int offset = 0; offset < prepared.node_dofs(part[i]); offset += 3) {
          Eigen::Vector3d u = offset == 0 ? rigid_motion(free_modes[k], x[i])
                                          : Eigen::Vector3d(free_modes[k].tail<3>() / size);
          if (axes != nullptr) u = axes->transpose() * u;
          for (int d = 0; d < 3; ++d)
            if (!is_prescribed[row_dof[row + offset + d]])
              W(row + offset + d, static_cast<int>(k)) = u[d];
        }
      }
    // The dofs that pin the free modes best: the first pivots of a column-pivoted QR of W^T over
    // the dofs the solver keeps (not prescribed, not eliminated by an equation).
    Eigen::MatrixXd candidates = W;
    for (int row = 0; row < rows; ++row)
      if (is_known[row_dof[row]]) candidates.row(row).setZero();
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(candidates.transpose());
    for (std::size_t k = 0; k < free_modes.size(); ++k)
      fixing.push_back(row_dof[qr.colsPermutation().indices()[static_cast<int>(k)]]);
    for (int k = 0; k < W.cols(); ++k) {  // back to global components
      Eigen::VectorXd column = Eigen::VectorXd::Zero(prepared.active_dofs());
      for (int row = 0; row < rows; row += 3) {
        Eigen::Vector3d v = W.block<3, 1>(row, k);
        if (const Eigen::Matrix3d* axes = rotations.of(prepared.node_of(row_dof[row])))
          v = *axes * v;
        column.segment<3>(row_dof[row]) = v;
      }
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

// The report of a body held only by contact that slides: its free motion u = R v, fitted as
// u = t + w x (x - c) over the nodes it moves, named as a translation along t or a rotation about
// w (through a point of the axis), with the load along the motion and the capacity turned into a
// force or a moment about the axis (G_v^T lambda = |t| F_t or |w| M_w); how many contact nodes
// slip; a node of the body.
std::string sliding_report(const Model& model, const PreparedModel& prepared,
                           const FloatingBodies& floating, const contact::EquilibriumLoss& loss) {
  const Eigen::VectorXd u = floating.modes * loss.motion;
  std::vector<int> moved;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int a = 0; a < prepared.active_nodes(); ++a)
    if (u.segment<3>(prepared.dof(a, 0)).norm() > 1e-12 * u.cwiseAbs().maxCoeff()) {
      moved.push_back(a);
      const Vec3& x = model.coords[prepared.node_of_active[a]];
      centre += Eigen::Vector3d(x[0], x[1], x[2]);
    }
  if (moved.empty()) return "a body held only by contact slides: friction capacity exceeded";
  centre /= static_cast<double>(moved.size());
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  double size = 0.0;
  for (int a : moved) {
    const Vec3& x = model.coords[prepared.node_of_active[a]];
    const Eigen::Vector3d r = Eigen::Vector3d(x[0], x[1], x[2]) - centre;
    size = std::max(size, r.norm());
    Eigen::Matrix3d cross;  // [r]x, so that w x r = -[r]x w
    cross << 0, -r[2], r[1], r[2], 0, -r[0], -r[1], r[0], 0;
    Eigen::Matrix<double, 3, 6> A;
    A << Eigen::Matrix3d::Identity(), -cross;  // u = t + w x r
    normal += A.transpose() * A;
    rhs += A.transpose() * u.segment<3>(prepared.dof(a, 0));
  }
  const Eigen::Matrix<double, 6, 1> tw = normal.ldlt().solve(rhs);
  // Components below 1e-9 of the motion are round-off of an exact axis: shown as 0.
  Eigen::Vector3d t = tw.head<3>(), w = tw.tail<3>();
  for (Eigen::Vector3d* v : {&t, &w}) {
    const double largest = v->cwiseAbs().maxCoeff();
    for (int d = 0; d < 3; ++d)
      if (std::abs((*v)[d]) <= 1e-9 * largest) (*v)[d] = 0.0;
  }
  std::string motion, units;
  double scale = 1.0;
  if (w.norm() * std::max(size, 1e-300) <= 1e-6 * t.norm()) {
    const Eigen::Vector3d e = t.normalized();
    motion = text("translation along (%.3g, %.3g, %.3g)", e[0], e[1], e[2]);
    scale = t.norm();
    units = "force";
  } else {
    const Eigen::Vector3d e = w.normalized(), p = centre + w.cross(t) / w.squaredNorm();
    motion = text("rotation about (%.3g, %.3g, %.3g)", e[0], e[1], e[2]) +
             text(" through (%.4g, %.4g, %.4g)", p[0], p[1], p[2]);
    scale = w.norm();
    units = "moment";
  }
  return "the body held only by contact (the part of node " +
         std::to_string(model.node_ids[prepared.node_of_active[moved.front()]]) +
         ") slides: friction capacity exceeded (" + std::to_string(loss.slipping) +
         " nodes slipping, " + units +
         text(" applied %.6g, capacity %.6g", loss.applied / scale, loss.capacity / scale) +
         ", along its free " + motion + ")";
}

}  // namespace styk::solver_detail
