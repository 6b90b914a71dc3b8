// Fill-reducing ordering computed on the NODE graph (3x fewer vertices and 9x fewer edges than
// the dof graph, same fill) and expanded to the free dofs of each node (`dof_offset`: the layout
// of PreparedModel).
#pragma once

#include <cstdint>
#include <vector>

#include "linear_solver.hpp"
#include "stiffness_matrix.hpp"

namespace styk::solver_detail {

// METIS nested dissection of the nodes having a free dof. Returns perm with perm[k] = free dof
// index eliminated k-th (the CHOLMOD "Perm" convention), or an empty vector when METIS fails.
std::vector<std::int64_t> metis_free_dof_ordering(const NodeGraph& graph,
                                                  const std::vector<int>& dof_offset,
                                                  const DofPartition& partition);

}  // namespace styk::solver_detail
