// One Newton step of the active-set iteration: the linearised complementarity conditions of the
// closed constraints under the current statuses, with the equilibrium of the bodies held only by
// contact, assembled densely and solved by LU (dense_lu.hpp), or handed to the structure operator
// when S is not held (structure_operator.hpp).
#include <algorithm>
#include <cmath>
#include <memory>

#include "active_set_parts.hpp"
#include "dense_lu.hpp"

namespace styk::contact::active_set_detail {
namespace {

// The system A x = rhs for x = (the closed constraints' live multipliers, the rigid motions),
// stored as A^T: it is assembled a row of A at a time, and column-major A^T keeps each row
// contiguous (row-wise writes into column-major A made the assembly a quarter of an iteration on
// SPEC 4.2 model B's 7206 unknowns). DenseLu factorises A^T and solves with A
// (Storage::transposed).
struct LinearisedSystem {
  std::vector<int> unknowns;  // global rows 3 node + component of the multipliers
  Eigen::MatrixXd At;         // A^T: column r is row r of A
  Eigen::VectorXd rhs;
};

std::vector<int> closed_unknowns(const Setup& setup, const std::vector<NodeStatus>& status) {
  std::vector<int> unknowns;
  for (std::size_t j = 0; j < status.size(); ++j)
    if (status[j] != NodeStatus::Open)
      for (int c = 0; c < 3; ++c)
        if (setup.live[j][c]) unknowns.push_back(static_cast<int>(3 * j) + c);
  return unknowns;
}

// Per closed node the rows Q d + D lambda = r of its statuses' linearisation (friction_law.hpp),
// with d = d0 - S lambda + G alpha: what does not involve S (NewtonRows), shared by the dense
// and the sparse solve.
NewtonRows newton_rows(const std::vector<ContactConstraint>& constraints,
                       const LinearContactSystem& system, const Loads& loads, const Setup& setup,
                       const std::vector<NodeStatus>& status, const Iterate& at,
                       const std::vector<ConstraintState>& previous, double eps, double proximal) {
  const int k = static_cast<int>(system.G.cols());
  NewtonRows out;
  out.unknowns = closed_unknowns(setup, status);
  const std::vector<int>& unknowns = out.unknowns;
  const int n = static_cast<int>(unknowns.size());
  out.q.resize(n);
  out.coupling.resize(n);
  out.rhs = Eigen::VectorXd::Zero(n);
  out.qg = Eigen::MatrixXd::Zero(n, k);
  out.g = Eigen::MatrixXd::Zero(n, k);
  for (int r = 0; r < n && k > 0; ++r) out.g.row(r) = system.G.row(unknowns[r]);
  out.h = loads.h;
  for (int i = 0; i < n;) {
    const int node = unknowns[i] / 3;
    int end = i;
    while (end < n && unknowns[end] / 3 == node) ++end;
    const LocalPoint p = point_of(constraints[node], setup, node, at.lambda.segment<3>(3 * node),
                                  at.d.segment<3>(3 * node), previous[node].d_ref, eps, proximal);
    const LocalRows rows = linearise(p, status[node]);
    const Eigen::Vector3d d0 = loads.d0.segment<3>(3 * node);
    for (int r = i; r < end; ++r) {
      const int c = unknowns[r] % 3;
      out.q[r] = rows.Q.row(c).transpose();
      for (int s = i; s < end; ++s) out.coupling[r].emplace_back(s, rows.D(c, unknowns[s] % 3));
      out.rhs[r] = rows.r[c] - out.q[r].dot(d0);
      if (k > 0) out.qg.row(r) = out.q[r].transpose() * system.G.middleRows<3>(3 * node);
    }
    i = end;
  }
  return out;
}

// The dense system of `rows`: row r of A is -q[r] . S(node's rows, unknowns) + coupling + qg,
// then the rigid equilibrium G^T lambda = h. S is symmetric (exactly: ContactOperator::compliance
// symmetrises it), so the node's rows of S restricted to the unknowns are read down its three
// columns.
LinearisedSystem assemble_dense(const LinearContactSystem& system, const NewtonRows& rows) {
  const int k = static_cast<int>(system.G.cols());
  LinearisedSystem out;
  out.unknowns = rows.unknowns;
  const std::vector<int>& unknowns = out.unknowns;
  const int n = static_cast<int>(unknowns.size());
  out.At = Eigen::MatrixXd::Zero(n + k, n + k);
  out.rhs = Eigen::VectorXd::Zero(n + k);
  Eigen::MatrixXd S_columns(n, 3);  // S(unknowns, node's three components)
  int loaded_node = -1;
  for (int r = 0; r < n; ++r) {
    const int node = unknowns[r] / 3;
    if (node != loaded_node) {
      for (int m = 0; m < 3; ++m) {
        const double* column = system.S.col(3 * node + m).data();
        for (int j = 0; j < n; ++j) S_columns(j, m) = column[unknowns[j]];
      }
      loaded_node = node;
    }
    out.At.col(r).head(n).noalias() = -S_columns * rows.q[r];
    for (const auto& [s, v] : rows.coupling[r]) out.At(s, r) += v;
    if (k > 0) out.At.col(r).tail(k) = rows.qg.row(r).transpose();
    out.rhs[r] = rows.rhs[r];
  }
  for (int a = 0; a < k; ++a) {
    out.At.col(n + a).head(n) = rows.g.col(a);
    out.rhs[n + a] = rows.h[a];
  }
  return out;
}

// Rows mix units (displacement rows of S, force^2 rows of the slip law, force rows of the rigid
// equilibrium): they are equilibrated so the condition estimate means something. False when a row
// or column is empty. Rows of A are columns of the stored A^T.
bool equilibrate(LinearisedSystem& system) {
  Eigen::MatrixXd& At = system.At;
  const Eigen::Index size = At.rows();
  Eigen::VectorXd column_largest = Eigen::VectorXd::Zero(size);  // per column of A
  for (Eigen::Index r = 0; r < size; ++r) {
    const double largest = At.col(r).cwiseAbs().maxCoeff();
    if (!(largest > 0.0)) return false;  // e.g. a free rigid motion no closed node touches
    At.col(r) /= largest;
    system.rhs[r] /= largest;
    column_largest = column_largest.cwiseMax(At.col(r).cwiseAbs());
  }
  for (Eigen::Index c = 0; c < size; ++c)
    if (!(column_largest[c] > 1e-14)) return false;
  return true;
}

// The nodes whose statuses differ between two status sets of the same constraints.
int status_changes(const std::vector<NodeStatus>& a, const std::vector<NodeStatus>& b) {
  if (a.size() != b.size()) return static_cast<int>(std::max(a.size(), b.size()));
  int changes = 0;
  for (std::size_t j = 0; j < a.size(); ++j) changes += a[j] != b[j] ? 1 : 0;
  return changes;
}

// Solves the system (A consumed) under `status`; false when it is singular. A system of the
// unknowns of the kept factor, with few statuses changed since, tries GMRES with it first. That
// solve is accepted only at a direct solve's backward error and skips the condition test below
// (which the kept factor passed). A body held only by contact that loses its hold is caught
// before the solve (body_hold), not by that test; a system that the few changed statuses made
// singular otherwise (slip directions leaving a rotation free) is refused only when its
// right-hand side lies outside its range, where no solve reaches that backward error.
bool solve_equilibrated(LinearisedSystem& system, const std::vector<NodeStatus>& status,
                        const ActiveSetOptions& options, LinearisedFactor* factor,
                        Eigen::VectorXd& x) {
  if (!equilibrate(system)) return false;
  const bool reusable =
      factor != nullptr && system.At.rows() >= options.reuse_factor_size && system.At.rows() > 0;
  if (reusable && factor->refine_next && factor->lu && factor->unknowns == system.unknowns &&
      status_changes(factor->statuses, status) <= options.reuse_status_changes) {
    int iterations = 0;
    if (factor->lu->solve_by_krylov(system.At, system.rhs, x, options.reuse_krylov_iterations,
                                    iterations)) {
      ++factor->reused;
      return true;
    }
  }
  auto lu = std::make_unique<contact_detail::DenseLu>(std::move(system.At),
                                                      contact_detail::DenseLu::Storage::transposed);
  if (!lu->factorised() || !(lu->rcond() > 1e-15)) return false;
  x = lu->solve(system.rhs);
  if (reusable) {
    factor->lu = std::move(lu);
    factor->unknowns = system.unknowns;
    factor->statuses = status;
  }
  return x.allFinite();
}

}  // namespace

bool solve_linearised(const std::vector<ContactConstraint>& constraints,
                      const LinearContactSystem& system, const Loads& loads, const Setup& setup,
                      const std::vector<NodeStatus>& status, const Iterate& at,
                      const std::vector<ConstraintState>& previous, double eps, double proximal,
                      const ActiveSetOptions& options, LinearisedFactor* factor, Iterate& out) {
  const int m = static_cast<int>(constraints.size());
  const int k = static_cast<int>(system.G.cols());
  const NewtonRows rows =
      newton_rows(constraints, system, loads, setup, status, at, previous, eps, proximal);
  const int n = static_cast<int>(rows.unknowns.size());
  out.lambda = Eigen::VectorXd::Zero(3 * m);
  out.alpha = Eigen::VectorXd::Zero(k);
  if (n + k == 0) {
    out.d = displacements(system, loads, out);
    return true;
  }
  Eigen::VectorXd x;
  if (system.structure) {
    Eigen::VectorXd s_lambda;
    if (!system.structure->solve(rows, x, s_lambda) || !x.allFinite()) return false;
    for (int j = 0; j < n; ++j) out.lambda[rows.unknowns[j]] = x[j];
    out.alpha = x.tail(k);
    out.d = loads.d0 - s_lambda;
    if (k > 0) out.d += system.G * out.alpha;
    return true;
  }
  LinearisedSystem linearised = assemble_dense(system, rows);
  if (!solve_equilibrated(linearised, status, options, factor, x)) return false;
  for (int j = 0; j < n; ++j) out.lambda[rows.unknowns[j]] = x[j];
  out.alpha = x.tail(k);
  out.d = displacements(system, loads, out);
  return true;
}

}  // namespace styk::contact::active_set_detail
