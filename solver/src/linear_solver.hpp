// The interface between the step driver and a linear solver backend (CHOLMOD, PETSc GAMG), plus
// the bookkeeping both share: which active dofs are free, and the coupling K_fp between free and
// prescribed dofs that moves prescribed displacements to the right-hand side.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "step_conditions.hpp"
#include "stiffness_matrix.hpp"

namespace styk::solver_detail {

struct DofPartition {
  std::vector<int> free_of_dof;   // per active dof: index among the free dofs, -1 if prescribed
  std::vector<int> free_dofs;     // free index -> active dof
  std::vector<int> prescribed;    // sorted active dofs with a prescribed value
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
};

// Thrown by a direct solver whose factor would not fit in memory (the analysis may then switch to
// the iterative solver).
class FactorTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
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

  // Solves K_ff X = F_f for `columns` right-hand sides at once, prescribed dofs held at zero (the
  // contact compliance needs one column per contact constraint). F and X are column-major,
  // active_dofs() rows; prescribed rows of X are zero. The default solves column by column;
  // a direct solver overrides it with one blocked triangular solve.
  virtual std::vector<double> solve_homogeneous(const std::vector<double>& F, int columns);
};

std::unique_ptr<LinearSolver> make_cholmod_solver(const SolverContext& context);
// nullptr when this build has no PETSc.
std::unique_ptr<LinearSolver> make_gamg_solver(const SolverContext& context, double tolerance);

}  // namespace styk::solver_detail
