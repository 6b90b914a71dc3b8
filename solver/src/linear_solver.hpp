// The interface between the step driver and a linear solver backend (CHOLMOD, PETSc GAMG), plus
// the bookkeeping both share: which active dofs are free, and the coupling K_fp between free and
// prescribed dofs that moves prescribed displacements to the right-hand side.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "step_conditions.hpp"
#include "stiffness_matrix.hpp"
#include "styk/core/diagnostics.hpp"

namespace styk::solver_detail {

struct DofPartition {
  std::vector<int> free_of_dof;  // per active dof: index among the free dofs, -1 if prescribed
  std::vector<int> free_dofs;    // free index -> active dof
  std::vector<int> prescribed;   // sorted active dofs with a prescribed value
  int free_count() const { return static_cast<int>(free_dofs.size()); }
};

DofPartition partition_dofs(int active_dofs, const std::vector<int>& prescribed);

// Entries K(r, c) with r free and c prescribed, as (free index of r, active dof c, value).
struct CouplingEntry {
  int free_row;
  int dof;
  double value;
};
std::vector<CouplingEntry> extract_coupling(const StiffnessMatrix& K,
                                            const DofPartition& partition);

// rhs_f = f_f - K_fp u_p over the free dofs; `prescribed_value` is indexed by active dof.
std::vector<double> free_rhs(const std::vector<double>& f, const DofPartition& partition,
                             const std::vector<CouplingEntry>& coupling,
                             const std::vector<double>& prescribed_value);

// What the analysis needs to know to name things in messages.
struct SolverContext {
  const Model& model;
  const PreparedModel& prepared;
  const PhaseRecorder& phases;
  int threads = 1;
  double memory_limit_gb = 0.0;  // SolveOptions::memory_limit_gb
  // Direct solvers refine solve()'s answer in extended precision (extended_refinement.hpp).
  bool refine_solutions = true;
};

// Thrown by a direct solver whose factor would not fit in memory (the analysis may then switch to
// the iterative solver).
class FactorTooLarge : public ResourceLimitError {
 public:
  using ResourceLimitError::ResourceLimitError;
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string description() const = 0;

  // Prepares to solve with K (all active dofs, pristine) and the prescribed dofs of `partition`
  // (ordering, factorisation or preconditioner set-up). May modify or release K's values, which
  // must stay alive and untouched until the solver is destroyed.
  virtual void prepare(StiffnessMatrix& K, const DofPartition& partition) = 0;

  // Displacements u on all active dofs for external forces f and prescribed displacements
  // (prescribed_value indexed by active dof; only prescribed entries are read).
  virtual std::vector<double> solve(const std::vector<double>& f,
                                    const std::vector<double>& prescribed_value) = 0;

  virtual int iterations() const { return 0; }  // of the last solve (iterative solvers)

  // Entries of the direct factor of K_ff from its symbolic analysis (deterministic, unlike a
  // timing); 0 when the backend does not say.
  virtual double factor_nonzeros() const { return 0.0; }

  // Solves K_ff X = F_f for `columns` right-hand sides at once, prescribed dofs held at zero (the
  // contact compliance needs one column per contact constraint). F and X are column-major,
  // active_dofs() rows; prescribed rows of X are zero. The default solves column by column;
  // a direct solver overrides it with one blocked triangular solve.
  virtual std::vector<double> solve_homogeneous(const std::vector<double>& F, int columns);

  // Rows `rows` (active dofs) of X = K_ff^-1 F for sparse right-hand sides F (prescribed dofs held
  // at zero, prescribed entries of F ignored), handed to `sink` in blocks of at most `block`
  // columns: sink(columns, values) with `columns` the indices into F of the block and `values`
  // rows.size() x columns.size() (prescribed rows zero). The contact compliance needs X only at
  // the contact dofs. The default solves dense blocks with solve_homogeneous; a supernodal factor
  // overrides it with substitutions restricted to the factor's columns the right-hand sides and
  // the wanted rows reach. The sink may be called from several threads at once, never twice for
  // the same column.
  struct SparseColumn {
    std::vector<int> dof;  // active dofs
    std::vector<double> value;
  };
  using ColumnBlockSink =
      std::function<void(const std::vector<int>& columns, const Eigen::MatrixXd& values)>;
  virtual void solve_sparse_columns(const std::vector<SparseColumn>& F,
                                    const std::vector<int>& rows, int active_dofs, int block,
                                    const ColumnBlockSink& sink);
};

std::unique_ptr<LinearSolver> make_cholmod_solver(const SolverContext& context);
// nullptr when this build has no PETSc.
std::unique_ptr<LinearSolver> make_gamg_solver(const SolverContext& context, double tolerance);

}  // namespace styk::solver_detail
