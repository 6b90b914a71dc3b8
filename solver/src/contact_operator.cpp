#include "contact_operator.hpp"

#include <algorithm>

namespace styk::solver_detail {

ContactOperator::ContactOperator(const PreparedModel& prepared,
                                 const std::vector<contact::ContactConstraint>& constraints) {
  ptr_.push_back(0);
  for (const contact::ContactConstraint& c : constraints)
    for (int component = 0; component < 3; ++component) {
      const Eigen::Vector3d row = c.row(component);
      used_.push_back(component == 0 || c.scale(component) > 0.0);
      auto add = [&](int node, double weight) {
        const int a = prepared.active_of_node[node];
        for (int d = 0; d < 3; ++d)
          if (row[d] != 0.0) {
            dof_.push_back(prepared.dof(a, d));
            value_.push_back(weight * row[d]);
          }
      };
      add(c.slave, 1.0);
      for (const contact::MasterTerm& t : c.master) add(t.node, -t.weight);
      ptr_.push_back(static_cast<int>(dof_.size()));
    }
}

Eigen::VectorXd ContactOperator::apply(const std::vector<double>& u) const {
  const Eigen::Map<const Eigen::VectorXd> map(u.data(), static_cast<Eigen::Index>(u.size()));
  return apply(Eigen::Ref<const Eigen::VectorXd>(map));
}

Eigen::VectorXd ContactOperator::apply(const Eigen::Ref<const Eigen::VectorXd>& u) const {
  Eigen::VectorXd out(rows());
  for (int i = 0; i < rows(); ++i) {
    double sum = 0.0;
    for (int p = ptr_[i]; p < ptr_[i + 1]; ++p) sum += value_[p] * u[dof_[p]];
    out[i] = sum;
  }
  return out;
}

Eigen::MatrixXd ContactOperator::apply_columns(const Eigen::MatrixXd& U) const {
  Eigen::MatrixXd out(rows(), U.cols());
  for (int k = 0; k < U.cols(); ++k)
    out.col(k) = apply(Eigen::Ref<const Eigen::VectorXd>(U.col(k)));
  return out;
}

void ContactOperator::add_transpose(const Eigen::VectorXd& lambda, double factor,
                                    std::vector<double>& f) const {
  for (int i = 0; i < rows(); ++i)
    for (int p = ptr_[i]; p < ptr_[i + 1]; ++p) f[dof_[p]] += factor * value_[p] * lambda[i];
}

Eigen::MatrixXd ContactOperator::compliance(LinearSolver& solver, int active_dofs,
                                            const ModelConstraints& kinematic, int block) const {
  std::vector<int> columns;
  for (int i = 0; i < rows(); ++i)
    if (row_used(i)) columns.push_back(i);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(rows(), rows());
  if (kinematic.empty()) {
    // S_ij = B_i K^-1 B_j^T needs K^-1 B_j^T only at the dofs B touches: sparse right-hand sides,
    // few wanted rows (LinearSolver::solve_sparse_columns).
    std::vector<LinearSolver::SparseColumn> F(columns.size());
    std::vector<int> local(active_dofs, -1), wanted;
    for (std::size_t j = 0; j < columns.size(); ++j)
      for (int p = ptr_[columns[j]]; p < ptr_[columns[j] + 1]; ++p) {
        F[j].dof.push_back(dof_[p]);
        F[j].value.push_back(value_[p]);
        if (local[dof_[p]] < 0) {
          local[dof_[p]] = static_cast<int>(wanted.size());
          wanted.push_back(dof_[p]);
        }
      }
    solver.solve_sparse_columns(F, wanted, active_dofs, block,
                                [&](const std::vector<int>& solved, const Eigen::MatrixXd& X) {
                                  for (std::size_t j = 0; j < solved.size(); ++j)
                                    for (int i : columns) {
                                      double sum = 0.0;
                                      for (int p = ptr_[i]; p < ptr_[i + 1]; ++p)
                                        sum += value_[p] * X(local[dof_[p]], j);
                                      S(i, columns[solved[j]]) = sum;
                                    }
                                });
    S = 0.5 * (S + S.transpose()).eval();
    return S;
  }
  const auto n = static_cast<std::size_t>(active_dofs);
  for (std::size_t first = 0; first < columns.size(); first += block) {
    const int count = static_cast<int>(std::min<std::size_t>(block, columns.size() - first));
    std::vector<double> F(n * count, 0.0);
    for (int j = 0; j < count; ++j) {
      const int i = columns[first + j];
      for (int p = ptr_[i]; p < ptr_[i + 1]; ++p) F[j * n + dof_[p]] += value_[p];
    }
    std::vector<double> column(kinematic.empty() ? 0 : n);
    if (!kinematic.empty())
      for (int j = 0; j < count; ++j) {
        std::copy(F.begin() + j * n, F.begin() + (j + 1) * n, column.begin());
        column =
            kinematic.reduced_forces(kinematic.plus_global(std::vector<double>(n, 0.0), column));
        std::copy(column.begin(), column.end(), F.begin() + j * n);
      }
    std::vector<double> X = solver.solve_homogeneous(F, count);
    if (!kinematic.empty())
      for (int j = 0; j < count; ++j) {
        std::copy(X.begin() + j * n, X.begin() + (j + 1) * n, column.begin());
        kinematic.to_global_displacements(column);
        std::copy(column.begin(), column.end(), X.begin() + j * n);
      }
    for (int j = 0; j < count; ++j) {
      const Eigen::Map<const Eigen::VectorXd> x(X.data() + j * n, active_dofs);
      const Eigen::VectorXd Bx = apply(Eigen::Ref<const Eigen::VectorXd>(x));
      for (int i : columns) S(i, columns[first + j]) = Bx[i];
    }
  }
  // Symmetric in exact arithmetic; symmetrise the round-off away.
  S = 0.5 * (S + S.transpose()).eval();
  return S;
}

std::vector<char> contact_nodes(const PreparedModel& prepared,
                                const std::vector<contact::ContactConstraint>& constraints) {
  std::vector<char> flags(prepared.active_nodes(), 0);
  for (const contact::ContactConstraint& c : constraints) {
    flags[prepared.active_of_node[c.slave]] = 1;
    for (const contact::MasterTerm& t : c.master) flags[prepared.active_of_node[t.node]] = 1;
  }
  return flags;
}

}  // namespace styk::solver_detail
