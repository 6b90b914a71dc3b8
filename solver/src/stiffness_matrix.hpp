// The global stiffness on all active dofs, stored as scalar CSR (both triangles, columns sorted)
// whose pattern comes from the NODE graph: node a couples to node b iff an element holds both, and
// every such pair is a dense block, dofs(a) x dofs(b) (3 or 6 each, PreparedModel's dof layout).
// The rows of node a share its column list, so entry (dof(a, i), dof(b, j)) sits at
// block_start(a, b) + i * row_stride(a) + j. With 3 dofs everywhere that is row_ptr[3a+i] + 3k + j,
// k = position of b in a's neighbour list. The arrays are laid out as PETSc's SeqAIJ expects, so
// the iterative solver wraps them without copying.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "prepared_model.hpp"

namespace styk::solver_detail {

struct NodeGraph {
  std::vector<std::int64_t> ptr;  // active node a: neighbours adj[ptr[a] .. ptr[a+1]), sorted,
  std::vector<int> adj;           // including a itself
  int nodes() const { return static_cast<int>(ptr.size()) - 1; }
};

// Element colouring for lock-free assembly: no two elements of one colour share a node.
struct ElementColouring {
  std::vector<int> ptr;  // colour c: elements order[ptr[c] .. ptr[c+1])
  std::vector<int> order;
  int colours() const { return static_cast<int>(ptr.size()) - 1; }
};

class StiffnessMatrix {
 public:
  // Builds the node graph and the scalar pattern (values zero). Throws InputError if the model is
  // too large for 32-bit sparse indices. `extra_couplings` are pairs of active nodes to couple
  // although no element holds both (both orders given; e.g. the fill of *EQUATION elimination).
  StiffnessMatrix(const Model& model, const PreparedModel& prepared, int threads,
                  const std::vector<std::pair<int, int>>& extra_couplings = {});

  const NodeGraph& graph() const { return graph_; }
  const ElementColouring& colouring() const { return colouring_; }
  int rows() const { return static_cast<int>(row_ptr_.size()) - 1; }
  std::int64_t nonzeros() const { return row_ptr_.empty() ? 0 : row_ptr_.back(); }

  // Position in values() of the block (a, b), row i = 0: the entry (dof(a, i), dof(b, j)) is at
  // block_start(a, b) + i * row_stride(a) + j. Returns -1 when a and b do not share an element.
  std::int64_t block_start(int a, int b) const;
  std::int64_t row_stride(int a) const {
    return row_ptr_[dof_offset_[a] + 1] - row_ptr_[dof_offset_[a]];
  }
  int node_dofs(int a) const { return dof_offset_[a + 1] - dof_offset_[a]; }
  int node_of(int dof) const;  // the active node of a dof
  // Position in values() of entry (dof i, dof j); -1 outside the pattern.
  std::int64_t entry_index(int i, int j) const;

  std::vector<int>& row_ptr() { return row_ptr_; }
  std::vector<int>& col() { return col_; }
  std::vector<double>& values() { return values_; }
  const std::vector<int>& row_ptr() const { return row_ptr_; }
  const std::vector<int>& col() const { return col_; }
  const std::vector<double>& values() const { return values_; }

  // True while values() hold the assembled stiffness unmodified (a solver may eliminate
  // prescribed dofs in place or release the values; the analysis then reassembles when needed).
  bool pristine() const { return pristine_; }
  void set_pristine(bool pristine) { pristine_ = pristine; }
  void release_values();  // frees the value array (the pattern stays)

 private:
  NodeGraph graph_;
  ElementColouring colouring_;
  std::vector<int> dof_offset_;     // the dof layout (PreparedModel::dof_offset)
  std::vector<int> column_offset_;  // per graph.adj entry: where neighbour b's columns start
  std::vector<int> row_ptr_;
  std::vector<int> col_;
  std::vector<double> values_;
  bool pristine_ = false;
};

}  // namespace styk::solver_detail
