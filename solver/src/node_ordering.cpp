#include "node_ordering.hpp"

#include <metis.h>

namespace styk::solver_detail {

std::vector<std::int64_t> metis_free_dof_ordering(const NodeGraph& graph,
                                                  const std::vector<int>& dof_offset,
                                                  const DofPartition& partition) {
  const int nodes = graph.nodes();
  auto has_free_dof = [&](int a) {
    for (int dof = dof_offset[a]; dof < dof_offset[a + 1]; ++dof)
      if (partition.free_of_dof[dof] >= 0) return true;
    return false;
  };
  std::vector<idx_t> vertex_of_node(nodes, -1);
  std::vector<int> node_of_vertex;
  for (int a = 0; a < nodes; ++a)
    if (has_free_dof(a)) {
      vertex_of_node[a] = static_cast<idx_t>(node_of_vertex.size());
      node_of_vertex.push_back(a);
    }
  idx_t vertices = static_cast<idx_t>(node_of_vertex.size());
  if (vertices == 0) return {};

  std::vector<idx_t> xadj(vertices + 1, 0);
  std::vector<idx_t> adjncy;
  adjncy.reserve(graph.adj.size());
  for (idx_t v = 0; v < vertices; ++v) {
    const int a = node_of_vertex[v];
    for (std::int64_t p = graph.ptr[a]; p < graph.ptr[a + 1]; ++p) {
      const idx_t w = vertex_of_node[graph.adj[p]];
      if (w >= 0 && w != v) adjncy.push_back(w);
    }
    xadj[v + 1] = static_cast<idx_t>(adjncy.size());
  }

  std::vector<idx_t> perm(vertices), iperm(vertices);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  if (METIS_NodeND(&vertices, xadj.data(), adjncy.data(), nullptr, options, perm.data(),
                   iperm.data()) != METIS_OK)
    return {};

  std::vector<std::int64_t> dof_perm;
  dof_perm.reserve(partition.free_count());
  for (idx_t k = 0; k < vertices; ++k) {
    const int a = node_of_vertex[perm[k]];
    for (int dof = dof_offset[a]; dof < dof_offset[a + 1]; ++dof) {
      const int free = partition.free_of_dof[dof];
      if (free >= 0) dof_perm.push_back(free);
    }
  }
  return dof_perm;
}

}  // namespace styk::solver_detail
