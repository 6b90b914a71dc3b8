// A linear system solved across the ranks of the MPI world (PETSc MPIAIJ, CG + GAMG or MUMPS).
// Every rank holds the model and the global sparsity pattern; each adds the rows its own elements
// produced (its part of the assembled matrix) and PETSc sums the parts into the rows' owners.
// The rows are split among the ranks by a graph partition of the nodes (rank_partition.hpp), each
// rank's nodes numbered consecutively in PETSc's rows. Prescribed dofs are
// eliminated symmetrically (rows and columns zeroed, the diagonal set to the mean free diagonal),
// as in the serial GAMG solver. No PETSc types in this header.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "extended_refinement.hpp"
#include "linear_coarse_space.hpp"
#include "linear_solver.hpp"
#include "phase_recorder.hpp"

namespace styk::solver_detail {

// Which rows each rank owns: rank r owns the PETSc rows [first[r], first[r + 1]). PETSc row p
// holds active dof dof_of_row[p] (a permutation that keeps each node's dofs consecutive, so the
// ranks' rows follow a graph partition of the mesh); empty permutation: row p is dof p.
struct RankRows {
  int rank = 0;
  int size = 1;
  std::vector<int> first;
  std::vector<int> row_of_dof;  // empty: the identity
  std::vector<int> dof_of_row;
  int begin() const { return first[rank]; }
  int end() const { return first[rank + 1]; }
  int owner(int row) const;  // the rank owning PETSc row `row`
  int row(int dof) const { return row_of_dof.empty() ? dof : row_of_dof[dof]; }
  int dof(int row) const { return dof_of_row.empty() ? row : dof_of_row[row]; }
};

// Contiguous ranges of about equal numbers of dofs, cut only between nodes (`dof_offset`: node a
// holds dofs dof_offset[a] .. dof_offset[a + 1]).
RankRows split_rows_by_nodes(const std::vector<int>& dof_offset, int rank, int size);

// A CSR matrix on all active dofs (both triangles, the global pattern; values may hold only this
// rank's part).
struct CsrView {
  const int* row_ptr = nullptr;
  const int* col = nullptr;
  const double* values = nullptr;
  int rows = 0;
};

struct DistributedSettings {
  bool direct = true;            // MUMPS Cholesky; otherwise CG + GAMG
  double tolerance = 1e-7;       // CG's relative residual
  double residual_limit = 1e-6;  // the true relative residual a solution must reach
  int block_size = 1;            // dofs per node when every node has the same number
  // 3 per active node for the rigid-body near-null space of GAMG (block size 3); empty: none.
  std::vector<double> coordinates;
  // Quadratic solids: the p-multigrid's linear level under CG (p_multigrid.hpp), with 3
  // coordinates per coarse node; none: plain GAMG.
  std::optional<LinearCoarseSpace> coarse;
  std::vector<double> corner_coordinates;
  bool refine = true;  // direct solver: refine solve()'s answer (extended_refinement.hpp)
  std::string what = "stiffness";  // names the matrix in messages
  SourceLoc where;                 // the deck, for a singular matrix
};

class DistributedSystem {
 public:
  // `K` holds the rows this rank owns whole (the values of other rows are not read): every rank
  // assembles the elements touching its rows (share_of_rank), so each row is summed in the
  // serial order and the distributed matrix is the serial one bit for bit. Collective.
  DistributedSystem(const RankRows& rows, const CsrView& K, const DofPartition& partition,
                    DistributedSettings settings, const PhaseRecorder& phases);
  ~DistributedSystem();
  DistributedSystem(const DistributedSystem&) = delete;
  DistributedSystem& operator=(const DistributedSystem&) = delete;

  // The solution on all active dofs, on every rank. `f` is the same on every rank (each owner
  // adds its rows); `prescribed_value` is indexed by active dof. Collective. The direct solver
  // refines its answer with residuals in extended precision (extended_refinement.hpp): the
  // serial solver's answer to the last bits.
  std::vector<double> solve(const std::vector<double>& f,
                            const std::vector<double>& prescribed_value);
  // Direct solver only: K_ff X = F for `columns` right-hand sides at once (column-major, active
  // dofs each, the same on every rank; prescribed dofs held at zero), X on every rank. One MUMPS
  // solve of a block (KSPMatSolve) instead of one per column: the contact compliance's columns.
  // Collective.
  std::vector<double> solve_homogeneous(const std::vector<double>& F, int columns);
  int iterations() const { return iterations_; }
  std::string description() const;

 private:
  struct Petsc;
  std::unique_ptr<Petsc> petsc_;
  RankRows rows_;
  std::vector<double> solve_once(const std::vector<double>& f,
                                 const std::vector<double>& prescribed_value,
                                 double* relative_residual);
  RefinementOutcome refine(const std::vector<double>& f, std::vector<double>& u);
  DofPartition partition_;
  DistributedSettings settings_;
  const PhaseRecorder& phases_;
  std::vector<CouplingEntry> coupling_;  // this rank's part of K_fp (free_row = active dof)
  // Direct solver: this rank's free rows of K, whole (prescribed columns included), for the
  // refinement's residual (extended_refinement.hpp); columns are active dofs.
  struct KeptRows {
    std::vector<int> dof, row_ptr{0}, col;
    std::vector<double> values;
  } kept_;
  double diagonal_ = 1.0;
  int iterations_ = 0;
};

// False when PETSC_OPTIONS has "-styk_p_multigrid false" (plain GAMG on quadratic meshes, for
// comparisons) or the build has no PETSc.
bool p_multigrid_requested();

}  // namespace styk::solver_detail
