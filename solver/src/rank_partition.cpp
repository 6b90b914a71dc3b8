#include "rank_partition.hpp"

#include <metis.h>

namespace styk::solver_detail {
namespace {

// METIS's node graph without self-loops; vertex weights are the nodes' dof counts so the parts
// hold about equal numbers of rows (beam and shell nodes carry 6, solid nodes 3).
bool metis_node_parts(const NodeGraph& graph, const std::vector<int>& dof_offset, int size,
                      std::vector<idx_t>& part) {
  idx_t vertices = graph.nodes();
  std::vector<idx_t> xadj(vertices + 1, 0), adjncy, weight(vertices);
  adjncy.reserve(graph.adj.size());
  for (idx_t a = 0; a < vertices; ++a) {
    for (std::int64_t p = graph.ptr[a]; p < graph.ptr[a + 1]; ++p)
      if (graph.adj[p] != a) adjncy.push_back(graph.adj[p]);
    xadj[a + 1] = static_cast<idx_t>(adjncy.size());
    weight[a] = dof_offset[a + 1] - dof_offset[a];
  }
  idx_t constraints = 1, parts = size, cut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1;  // the same partition on every rank and in every run
  part.assign(vertices, 0);
  return METIS_PartGraphKway(&vertices, &constraints, xadj.data(), adjncy.data(), weight.data(),
                             nullptr, nullptr, &parts, nullptr, nullptr, options, &cut,
                             part.data()) == METIS_OK;
}

}  // namespace

RankRows partition_rows_by_graph(const NodeGraph& graph, const std::vector<int>& dof_offset,
                                 int rank, int size) {
  const int nodes = graph.nodes();
  std::vector<idx_t> part;
  if (size <= 1 || nodes < size || !metis_node_parts(graph, dof_offset, size, part))
    return split_rows_by_nodes(dof_offset, rank, size);

  RankRows rows;
  rows.rank = rank;
  rows.size = size;
  const int dofs = dof_offset[nodes];
  rows.first.assign(size + 1, 0);
  for (int a = 0; a < nodes; ++a) rows.first[part[a] + 1] += dof_offset[a + 1] - dof_offset[a];
  for (int r = 0; r < size; ++r) rows.first[r + 1] += rows.first[r];
  rows.row_of_dof.assign(dofs, -1);
  rows.dof_of_row.assign(dofs, -1);
  std::vector<int> next(rows.first.begin(), rows.first.end() - 1);
  for (int a = 0; a < nodes; ++a)
    for (int dof = dof_offset[a]; dof < dof_offset[a + 1]; ++dof) {
      const int row = next[part[a]]++;
      rows.row_of_dof[dof] = row;
      rows.dof_of_row[row] = dof;
    }
  return rows;
}

long long cut_node_pairs(const NodeGraph& graph, const std::vector<int>& dof_offset,
                         const RankRows& rows) {
  const int nodes = graph.nodes();
  std::vector<int> owner(nodes);
  for (int a = 0; a < nodes; ++a)
    owner[a] = dof_offset[a + 1] > dof_offset[a] ? rows.owner(rows.row(dof_offset[a])) : -1;
  long long cut = 0;
  for (int a = 0; a < nodes; ++a)
    for (std::int64_t p = graph.ptr[a]; p < graph.ptr[a + 1]; ++p) {
      const int b = graph.adj[p];
      if (b > a && owner[a] >= 0 && owner[b] >= 0 && owner[a] != owner[b]) ++cut;
    }
  return cut;
}

}  // namespace styk::solver_detail
