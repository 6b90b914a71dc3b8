// Row ownership of distributed systems (no PETSc: also built without it).
#include <algorithm>

#include "distributed_system.hpp"

namespace styk::solver_detail {

int RankRows::owner(int row) const {
  const auto it = std::upper_bound(first.begin(), first.end(), row);
  return static_cast<int>(it - first.begin()) - 1;
}

RankRows split_rows_by_nodes(const std::vector<int>& dof_offset, int rank, int size) {
  RankRows rows;
  rows.rank = rank;
  rows.size = size;
  rows.first.assign(size + 1, 0);
  const int nodes = static_cast<int>(dof_offset.size()) - 1;
  const long long dofs = nodes > 0 ? dof_offset[nodes] : 0;
  int node = 0;
  for (int r = 1; r < size; ++r) {
    const long long target = dofs * r / size;
    while (node < nodes && dof_offset[node] < target) ++node;
    rows.first[r] = nodes > 0 ? dof_offset[node] : 0;
  }
  rows.first[size] = static_cast<int>(dofs);
  return rows;
}

}  // namespace styk::solver_detail
