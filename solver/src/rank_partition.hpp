// How the rows of a distributed system are shared among the MPI ranks: a graph partition of the
// mesh's nodes (METIS k-way, weighted by the nodes' dof counts), so that each rank owns a compact
// piece of the structure and few matrix entries couple rows of different ranks, whatever the
// deck's node numbering. Every rank computes the same partition (same graph, fixed seed).
#pragma once

#include <vector>

#include "distributed_system.hpp"
#include "stiffness_matrix.hpp"

namespace styk::solver_detail {

// Rank `rank` of `size`: its PETSc rows and the dof <-> row permutation. Nodes of one part are
// numbered consecutively in the order of their active index, and each node's dofs stay together
// in their order (3x3 blocks for PETSc's block size 3). One rank: the identity. When METIS cannot
// partition the graph the contiguous split of split_rows_by_nodes is returned.
RankRows partition_rows_by_graph(const NodeGraph& graph, const std::vector<int>& dof_offset,
                                 int rank, int size);

// The number of node pairs (graph edges) whose nodes' rows belong to different ranks: the
// coupling that crosses between ranks, i.e. the off-rank part of the matrix in node blocks.
long long cut_node_pairs(const NodeGraph& graph, const std::vector<int>& dof_offset,
                         const RankRows& rows);

}  // namespace styk::solver_detail
