#include "linear_solver.hpp"

#include <algorithm>

namespace styk::solver_detail {

DofPartition partition_dofs(int active_dofs, const std::vector<int>& prescribed) {
  DofPartition partition;
  partition.prescribed = prescribed;
  partition.free_of_dof.assign(active_dofs, 0);
  for (int dof : prescribed) partition.free_of_dof[dof] = -1;
  partition.free_dofs.reserve(active_dofs - prescribed.size());
  for (int dof = 0; dof < active_dofs; ++dof) {
    if (partition.free_of_dof[dof] < 0) continue;
    partition.free_of_dof[dof] = static_cast<int>(partition.free_dofs.size());
    partition.free_dofs.push_back(dof);
  }
  return partition;
}

std::vector<CouplingEntry> extract_coupling(const StiffnessMatrix& K,
                                            const DofPartition& partition) {
  // K is symmetric: K_fp entries are found in the rows of the prescribed dofs (few) rather than
  // by scanning every free row.
  std::vector<CouplingEntry> coupling;
  const std::vector<int>& row_ptr = K.row_ptr();
  for (int c : partition.prescribed)
    for (int p = row_ptr[c]; p < row_ptr[c + 1]; ++p) {
      const int r = K.col()[p];
      const int free_row = partition.free_of_dof[r];
      if (free_row >= 0 && K.values()[p] != 0.0) coupling.push_back({free_row, c, K.values()[p]});
    }
  return coupling;
}

std::vector<double> free_rhs(const std::vector<double>& f, const DofPartition& partition,
                             const std::vector<CouplingEntry>& coupling,
                             const std::vector<double>& prescribed_value) {
  std::vector<double> rhs(partition.free_count());
  for (int i = 0; i < partition.free_count(); ++i) rhs[i] = f[partition.free_dofs[i]];
  for (const CouplingEntry& entry : coupling)
    rhs[entry.free_row] -= entry.value * prescribed_value[entry.dof];
  return rhs;
}

std::vector<double> LinearSolver::solve_homogeneous(const std::vector<double>& F, int columns) {
  const std::size_t rows = columns > 0 ? F.size() / static_cast<std::size_t>(columns) : 0;
  std::vector<double> X(F.size());
  const std::vector<double> zero(rows, 0.0);
  for (int j = 0; j < columns; ++j) {
    const std::vector<double> f(F.begin() + j * rows, F.begin() + (j + 1) * rows);
    const std::vector<double> x = solve(f, zero);
    std::copy(x.begin(), x.end(), X.begin() + j * rows);
  }
  return X;
}

void LinearSolver::solve_sparse_columns(const std::vector<SparseColumn>& F,
                                        const std::vector<int>& rows, int active_dofs, int block,
                                        const ColumnBlockSink& sink) {
  const int total = static_cast<int>(F.size());
  const auto n = static_cast<std::size_t>(active_dofs);
  block = std::max(block, 1);
  for (int first = 0; first < total; first += block) {
    const int count = std::min(block, total - first);
    std::vector<double> dense(n * count, 0.0);
    std::vector<int> columns(count);
    for (int j = 0; j < count; ++j) {
      columns[j] = first + j;
      const SparseColumn& f = F[first + j];
      for (std::size_t p = 0; p < f.dof.size(); ++p) dense[j * n + f.dof[p]] += f.value[p];
    }
    const std::vector<double> X = solve_homogeneous(dense, count);
    Eigen::MatrixXd values(rows.size(), count);
    for (int j = 0; j < count; ++j)
      for (std::size_t r = 0; r < rows.size(); ++r) values(r, j) = X[j * n + rows[r]];
    sink(columns, values);
  }
}

}  // namespace styk::solver_detail
