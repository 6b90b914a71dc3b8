#include "contact_operator.hpp"

#include <algorithm>
#include <map>

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

ContactOperator::ReducedRows ContactOperator::reduced_rows(
    int active_dofs, const ModelConstraints& kinematic) const {
  // Per active dof: the reduced nodal dofs and coefficients it is made of (itself; a dependent
  // dof its masters' combination).
  std::vector<std::vector<std::pair<int, double>>> made_of(active_dofs);
  for (int d = 0; d < active_dofs; ++d) made_of[d] = {{d, 1.0}};
  for (const DependentDof& dependent : kinematic.equations().dependents())
    made_of[dependent.dof] = dependent.masters;
  const NodeRotations& rotations = kinematic.rotations();
  // Global component c of node a in nodal dofs: u_c = sum_k R(c, k) w_k.
  const auto nodal_terms = [&](int dof) {
    const int a = dof / 3, c = dof % 3;
    std::vector<std::pair<int, double>> out;
    const Eigen::Matrix3d* R = rotations.of(a);
    for (int k = 0; k < 3; ++k) {
      const double r = R != nullptr ? (*R)(c, k) : (k == c ? 1.0 : 0.0);
      if (r == 0.0) continue;
      for (const auto& [j, coefficient] : made_of[3 * a + k]) out.emplace_back(j, r * coefficient);
    }
    return out;
  };
  ReducedRows rows(this->rows());
  for (int i = 0; i < this->rows(); ++i) {
    if (!row_used(i)) continue;
    std::map<int, double> sum;
    for (int p = ptr_[i]; p < ptr_[i + 1]; ++p)
      for (const auto& [j, coefficient] : nodal_terms(dof_[p])) sum[j] += value_[p] * coefficient;
    for (const auto& [j, v] : sum)
      if (v != 0.0) rows[i].emplace_back(j, v);
  }
  return rows;
}

LinearSolver::SparseColumn ContactOperator::sparse_column(
    const std::vector<std::pair<int, double>>& row, std::vector<int>& local,
    std::vector<int>& wanted) {
  LinearSolver::SparseColumn column;
  for (const auto& [dof, v] : row) {
    column.dof.push_back(dof);
    column.value.push_back(v);
    if (local[dof] < 0) {
      local[dof] = static_cast<int>(wanted.size());
      wanted.push_back(dof);
    }
  }
  return column;
}

Eigen::MatrixXd ContactOperator::compliance(LinearSolver& solver, int active_dofs,
                                            const ModelConstraints& kinematic, int block) const {
  const ReducedRows row_terms = reduced_rows(active_dofs, kinematic);
  std::vector<int> columns;
  for (int i = 0; i < rows(); ++i)
    if (row_used(i)) columns.push_back(i);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(rows(), rows());
  // B^T e_i in reduced nodal dofs (the transpose of the same map) and the wanted dofs: the nodal
  // dofs of the contact nodes, or the masters of those that are dependent.
  std::vector<LinearSolver::SparseColumn> F;
  std::vector<int> wanted;
  std::vector<int> local(active_dofs, -1);  // per active dof: index into wanted
  for (int i : columns) F.push_back(sparse_column(row_terms[i], local, wanted));
  // S_ij = (B R P)_i x_j: row i's reduced terms dotted with the solution at the wanted dofs.
  solver.solve_sparse_columns(F, wanted, active_dofs, block,
                              [&](const std::vector<int>& solved, const Eigen::MatrixXd& X) {
                                for (std::size_t j = 0; j < solved.size(); ++j)
                                  for (int i : columns) {
                                    double sum = 0.0;
                                    for (const auto& [dof, v] : row_terms[i])
                                      sum += v * X(local[dof], j);
                                    S(i, columns[solved[j]]) = sum;
                                  }
                              });
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
