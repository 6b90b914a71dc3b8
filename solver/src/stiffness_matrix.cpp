#include "stiffness_matrix.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>

#include "parallel.hpp"

namespace styk::solver_detail {
namespace {

// Elements of each active node (CSR over active nodes).
void node_elements(const Model& model, const PreparedModel& prepared, std::vector<int>& ptr,
                   std::vector<int>& elements) {
  const int nodes = prepared.active_nodes();
  ptr.assign(nodes + 1, 0);
  for (int e = 0; e < model.element_count(); ++e) {
    const int* en = model.element_nodes(e);
    for (int k = 0; k < model.elements[e].node_count; ++k)
      ++ptr[prepared.active_of_node[en[k]] + 1];
  }
  for (int a = 0; a < nodes; ++a) ptr[a + 1] += ptr[a];
  elements.resize(ptr[nodes]);
  std::vector<int> fill(ptr.begin(), ptr.end() - 1);
  for (int e = 0; e < model.element_count(); ++e) {
    const int* en = model.element_nodes(e);
    for (int k = 0; k < model.elements[e].node_count; ++k)
      elements[fill[prepared.active_of_node[en[k]]]++] = e;
  }
}

NodeGraph build_node_graph(const Model& model, const PreparedModel& prepared, int threads) {
  std::vector<int> ne_ptr, ne;
  node_elements(model, prepared, ne_ptr, ne);
  const int nodes = prepared.active_nodes();
  threads = resolve_threads(threads);
  // Per-thread markers: marker[b] == a + 1 once b is recorded as a neighbour of a.
  std::vector<std::vector<int>> markers(threads);
  auto for_each_neighbour = [&](int a, std::vector<int>& marker, auto&& visit) {
    if (marker.empty()) marker.assign(nodes, 0);
    for (int p = ne_ptr[a]; p < ne_ptr[a + 1]; ++p) {
      const int e = ne[p];
      const int* en = model.element_nodes(e);
      for (int k = 0; k < model.elements[e].node_count; ++k) {
        const int b = prepared.active_of_node[en[k]];
        if (marker[b] != a + 1) {
          marker[b] = a + 1;
          visit(b);
        }
      }
    }
  };

  NodeGraph graph;
  graph.ptr.assign(nodes + 1, 0);
  parallel_for(nodes, threads, 512, [&](int begin, int end, int worker) {
    for (int a = begin; a < end; ++a) {
      std::int64_t count = 0;
      for_each_neighbour(a, markers[worker], [&](int) { ++count; });
      graph.ptr[a + 1] = count;
    }
  });
  for (int a = 0; a < nodes; ++a) graph.ptr[a + 1] += graph.ptr[a];
  graph.adj.resize(graph.ptr[nodes]);
  for (auto& marker : markers) std::fill(marker.begin(), marker.end(), 0);
  parallel_for(nodes, threads, 512, [&](int begin, int end, int worker) {
    for (int a = begin; a < end; ++a) {
      std::int64_t at = graph.ptr[a];
      for_each_neighbour(a, markers[worker], [&](int b) { graph.adj[at++] = b; });
      std::sort(graph.adj.begin() + graph.ptr[a], graph.adj.begin() + graph.ptr[a + 1]);
    }
  });
  return graph;
}

// Adds `extra` (sorted (a, b) pairs of active nodes) to the neighbour lists of `graph`.
void add_couplings(NodeGraph& graph, const std::vector<std::pair<int, int>>& extra) {
  if (extra.empty()) return;
  NodeGraph merged;
  merged.ptr.assign(graph.ptr.size(), 0);
  merged.adj.reserve(graph.adj.size() + extra.size());
  std::size_t next = 0;
  for (int a = 0; a < graph.nodes(); ++a) {
    const std::size_t start = merged.adj.size();
    merged.adj.insert(merged.adj.end(), graph.adj.begin() + graph.ptr[a],
                      graph.adj.begin() + graph.ptr[a + 1]);
    for (; next < extra.size() && extra[next].first == a; ++next)
      merged.adj.push_back(extra[next].second);
    std::sort(merged.adj.begin() + start, merged.adj.end());
    merged.adj.erase(std::unique(merged.adj.begin() + start, merged.adj.end()), merged.adj.end());
    merged.ptr[a + 1] = static_cast<std::int64_t>(merged.adj.size());
  }
  graph = std::move(merged);
}

// Greedy colouring with a 64-bit colour mask per node; elements that find all 64 colours taken
// around them go to another round of 64 colours.
ElementColouring colour_elements(const Model& model, const PreparedModel& prepared) {
  std::vector<int> colour(model.element_count(), -1);
  std::vector<int> pending(model.element_count());
  for (int e = 0; e < model.element_count(); ++e) pending[e] = e;
  std::vector<std::uint64_t> used(prepared.active_nodes());
  int base = 0;
  while (!pending.empty()) {
    std::fill(used.begin(), used.end(), 0);
    std::vector<int> left;
    for (int e : pending) {
      const int* en = model.element_nodes(e);
      const int n = model.elements[e].node_count;
      std::uint64_t taken = 0;
      for (int k = 0; k < n; ++k) taken |= used[prepared.active_of_node[en[k]]];
      if (taken == ~std::uint64_t{0}) {
        left.push_back(e);
        continue;
      }
      const int c = __builtin_ctzll(~taken);
      colour[e] = base + c;
      for (int k = 0; k < n; ++k) used[prepared.active_of_node[en[k]]] |= std::uint64_t{1} << c;
    }
    pending.swap(left);
    base += 64;
  }
  ElementColouring colouring;
  const int colours =
      model.element_count() == 0 ? 0 : *std::max_element(colour.begin(), colour.end()) + 1;
  colouring.ptr.assign(colours + 1, 0);
  for (int c : colour) ++colouring.ptr[c + 1];
  for (int c = 0; c < colours; ++c) colouring.ptr[c + 1] += colouring.ptr[c];
  colouring.order.resize(model.element_count());
  std::vector<int> fill(colouring.ptr.begin(), colouring.ptr.end() - 1);
  for (int e = 0; e < model.element_count(); ++e) colouring.order[fill[colour[e]]++] = e;
  return colouring;
}

}  // namespace

StiffnessMatrix::StiffnessMatrix(const Model& model, const PreparedModel& prepared, int threads,
                                 const std::vector<std::pair<int, int>>& extra_couplings)
    : graph_(build_node_graph(model, prepared, threads)),
      colouring_(colour_elements(model, prepared)),
      dof_offset_(prepared.dof_offset) {
  std::vector<std::pair<int, int>> extra = extra_couplings;
  std::sort(extra.begin(), extra.end());
  add_couplings(graph_, extra);
  const int nodes = graph_.nodes();
  // Row widths and where each neighbour's columns start in its row.
  column_offset_.resize(graph_.adj.size());
  std::vector<std::int64_t> width(nodes, 0);
  std::int64_t nonzeros = 0;
  for (int a = 0; a < nodes; ++a) {
    for (std::int64_t p = graph_.ptr[a]; p < graph_.ptr[a + 1]; ++p) {
      column_offset_[p] = static_cast<int>(width[a]);
      width[a] += node_dofs(graph_.adj[p]);
    }
    nonzeros += width[a] * node_dofs(a);
  }
  if (nonzeros > INT_MAX)
    throw InputError(SourceLoc{model.source, 0},
                     "the model is too large for this build: its stiffness matrix has " +
                         std::to_string(nonzeros) + " nonzeros, more than 32-bit indices hold");
  const int dofs = prepared.active_dofs();
  row_ptr_.resize(static_cast<std::size_t>(dofs) + 1);
  row_ptr_[0] = 0;
  for (int a = 0; a < nodes; ++a)
    for (int row = dof_offset_[a]; row < dof_offset_[a + 1]; ++row)
      row_ptr_[row + 1] = row_ptr_[row] + static_cast<int>(width[a]);
  col_.resize(nonzeros);
  parallel_for(nodes, resolve_threads(threads), 1024, [&](int begin, int end, int) {
    for (int a = begin; a < end; ++a)
      for (int row = dof_offset_[a]; row < dof_offset_[a + 1]; ++row) {
        int at = row_ptr_[row];
        for (std::int64_t p = graph_.ptr[a]; p < graph_.ptr[a + 1]; ++p) {
          const int b = graph_.adj[p];
          for (int j = dof_offset_[b]; j < dof_offset_[b + 1]; ++j) col_[at++] = j;
        }
      }
  });
  values_.assign(nonzeros, 0.0);
}

std::int64_t StiffnessMatrix::block_start(int a, int b) const {
  const auto first = graph_.adj.begin() + graph_.ptr[a];
  const auto last = graph_.adj.begin() + graph_.ptr[a + 1];
  const auto it = std::lower_bound(first, last, b);
  if (it == last || *it != b) return -1;
  return row_ptr_[dof_offset_[a]] + column_offset_[it - graph_.adj.begin()];
}

int StiffnessMatrix::node_of(int dof) const {
  return static_cast<int>(std::upper_bound(dof_offset_.begin(), dof_offset_.end(), dof) -
                          dof_offset_.begin()) -
         1;
}

std::int64_t StiffnessMatrix::entry_index(int i, int j) const {
  const int a = node_of(i), b = node_of(j);
  const std::int64_t start = block_start(a, b);
  if (start < 0) return -1;
  return start + (i - dof_offset_[a]) * row_stride(a) + (j - dof_offset_[b]);
}

void StiffnessMatrix::release_values() {
  std::vector<double>().swap(values_);
  pristine_ = false;
}

}  // namespace styk::solver_detail
