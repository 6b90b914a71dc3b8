#include "distributed_system.hpp"

#include <petscksp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "extended_refinement.hpp"
#include "ksp_progress.hpp"
#include "p_multigrid.hpp"
#include "petsc_runtime.hpp"
#include "rigid_body_modes.hpp"

namespace styk::solver_detail {
namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[240];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

struct DistributedSystem::Petsc {
  explicit Petsc(const PhaseRecorder& phases) : progress(phases) {}
  KspProgress progress;
  Mat A = nullptr;
  KSP ksp = nullptr;
  Vec b = nullptr;
  Vec x = nullptr;
  Vec r = nullptr;
  Vec all = nullptr;  // the whole solution, on every rank
  VecScatter to_all = nullptr;
  PMultigrid p_multigrid;  // referred to by the KSP's PC: destroyed after it
  ~Petsc() {
    VecScatterDestroy(&to_all);
    VecDestroy(&all);
    VecDestroy(&r);
    VecDestroy(&x);
    VecDestroy(&b);
    KSPDestroy(&ksp);
    MatDestroy(&A);
  }
};

namespace {

// Preallocation of the owned rows from the global pattern: columns inside / outside the owned
// range (PETSc's "diagonal" and "off-diagonal" parts).
void preallocate(Mat A, const RankRows& rows, const CsrView& K) {
  const int begin = rows.begin(), end = rows.end();
  std::vector<PetscInt> d_nnz(end - begin), o_nnz(end - begin);
  for (int row = begin; row < end; ++row) {
    const int dof = rows.dof(row);
    PetscInt inside = 0;
    for (int p = K.row_ptr[dof]; p < K.row_ptr[dof + 1]; ++p) {
      const int column = rows.row(K.col[p]);
      if (column >= begin && column < end) ++inside;
    }
    d_nnz[row - begin] = inside;
    o_nnz[row - begin] = (K.row_ptr[dof + 1] - K.row_ptr[dof]) - inside;
  }
  petsc_check(MatMPIAIJSetPreallocation(A, 0, d_nnz.data(), 0, o_nnz.data()),
              "MatMPIAIJSetPreallocation");
  petsc_check(MatSeqAIJSetPreallocation(A, 0, d_nnz.data()), "MatSeqAIJSetPreallocation");
}

void configure_solver(KSP ksp, Mat A, const RankRows& rows, const DistributedSettings& settings,
                      PMultigrid& p_multigrid) {
  // Tuning from the environment goes through this prefix (PETSC_OPTIONS="-styk_mpi_...").
  petsc_check(KSPSetOptionsPrefix(ksp, "styk_mpi_"), "KSPSetOptionsPrefix");
  PC pc = nullptr;
  petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
  if (settings.direct) {
    petsc_check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
    petsc_check(PCSetType(pc, PCCHOLESKY), "PCSetType");
    petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  } else {
    petsc_check(KSPSetType(ksp, KSPCG), "KSPSetType");
    petsc_check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    petsc_check(KSPSetTolerances(ksp, settings.tolerance, 0.0, PETSC_DEFAULT, 5000),
                "KSPSetTolerances");
    if (settings.coarse) {
      p_multigrid.configure(pc, A, *settings.coarse, settings.corner_coordinates, 0.01, &rows);
      petsc_check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
      return;
    }
    petsc_check(PCSetType(pc, PCGAMG), "PCSetType");
    petsc_check(PCGAMGSetType(pc, PCGAMGAGG), "PCGAMGSetType");
    petsc_check(PCGAMGSetNSmooths(pc, 1), "PCGAMGSetNSmooths");
    PetscReal threshold[] = {0.01};  // as the serial GAMG solver (gamg_solver.cpp)
    petsc_check(PCGAMGSetThreshold(pc, threshold, 1), "PCGAMGSetThreshold");
  }
  petsc_check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
}

// The coordinates of this rank's rows, in row order (3 per node: a node's rows are consecutive).
std::vector<double> owned_coordinates(const RankRows& rows, const std::vector<double>& by_dof) {
  std::vector<double> out;
  out.reserve(rows.end() - rows.begin());
  for (int row = rows.begin(); row < rows.end(); ++row) out.push_back(by_dof[rows.dof(row)]);
  return out;
}

// One line per rank on rank 0's progress: its rows and how long adding them took (how evenly the
// work is split).
void report_rank_shares(const RankRows& rows, double seconds, const PhaseRecorder& phases) {
  const double mine[2] = {static_cast<double>(rows.end() - rows.begin()), seconds};
  std::vector<double> all(2 * static_cast<std::size_t>(rows.size));
  MPI_Gather(mine, 2, MPI_DOUBLE, all.data(), 2, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  if (rows.rank != 0) return;
  for (int r = 0; r < rows.size; ++r)
    phases.info(
        format("rank %.0f: owns %.0f rows, added in %.2f s", r, all[2 * r], all[2 * r + 1]));
}

// The distributed vector x on every rank: scattered into `all` (the whole solution) and copied
// into u by active dof (u: the active dofs; prescribed dofs are left to the caller).
void gather_to_every_rank(VecScatter to_all, Vec all, const RankRows& rows, Vec x, double* u,
                          std::size_t dofs) {
  petsc_check(VecScatterBegin(to_all, x, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  petsc_check(VecScatterEnd(to_all, x, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* values = nullptr;
  petsc_check(VecGetArrayRead(all, &values), "VecGetArrayRead");
  for (std::size_t row = 0; row < dofs; ++row) u[rows.dof(static_cast<int>(row))] = values[row];
  VecRestoreArrayRead(all, &values);
}

InputError singular_matrix(const DistributedSettings& settings) {
  return InputError(settings.where, "the " + settings.what +
                                        " matrix is singular (MUMPS): the model is a mechanism or "
                                        "an element is degenerate");
}

}  // namespace

DistributedSystem::DistributedSystem(const RankRows& rows, const CsrView& K,
                                     const DofPartition& partition, DistributedSettings settings,
                                     const PhaseRecorder& phases)
    : petsc_(std::make_unique<Petsc>(phases)),
      rows_(rows),
      partition_(partition),
      settings_(std::move(settings)),
      phases_(phases) {
  PetscRuntime::ensure();
  const auto start = std::chrono::steady_clock::now();
  const int local = rows_.end() - rows_.begin();
  const std::vector<int>& free_of = partition_.free_of_dof;
  petsc_check(MatCreate(PETSC_COMM_WORLD, &petsc_->A), "MatCreate");
  Mat A = petsc_->A;
  petsc_check(MatSetSizes(A, local, local, K.rows, K.rows), "MatSetSizes");
  petsc_check(MatSetType(A, MATAIJ), "MatSetType");
  if (settings_.block_size > 1)
    petsc_check(MatSetBlockSize(A, settings_.block_size), "MatSetBlockSize");
  preallocate(A, rows_, K);

  // This rank's free rows and their coupling K_fp; and its part of the free diagonal, whose
  // global mean becomes the prescribed rows' diagonal.
  double diagonal_sum = 0.0;
  std::vector<PetscInt> columns;
  std::vector<PetscScalar> values;
  const bool keep = settings_.direct && settings_.refine;  // the rows for the refinement
  for (int global_row = rows_.begin(); global_row < rows_.end(); ++global_row) {
    const int row = rows_.dof(global_row);
    if (free_of[row] < 0) continue;
    columns.clear();
    values.clear();
    if (keep) kept_.dof.push_back(row);
    for (int p = K.row_ptr[row]; p < K.row_ptr[row + 1]; ++p) {
      const int c = K.col[p];
      if (keep && K.values[p] != 0.0) {
        kept_.col.push_back(c);
        kept_.values.push_back(K.values[p]);
      }
      if (free_of[c] < 0) {
        if (K.values[p] != 0.0) coupling_.push_back({row, c, K.values[p]});
        continue;
      }
      if (c == row) diagonal_sum += K.values[p];
      columns.push_back(rows_.row(c));
      values.push_back(K.values[p]);
    }
    if (keep) kept_.row_ptr.push_back(static_cast<int>(kept_.col.size()));
    const PetscInt petsc_row = global_row;
    petsc_check(MatSetValues(A, 1, &petsc_row, static_cast<PetscInt>(columns.size()),
                             columns.data(), values.data(), INSERT_VALUES),
                "MatSetValues");
  }
  MPI_Allreduce(MPI_IN_PLACE, &diagonal_sum, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  diagonal_ = partition_.free_count() > 0 && diagonal_sum > 0.0
                  ? diagonal_sum / partition_.free_count()
                  : 1.0;
  for (int row = rows_.begin(); row < rows_.end(); ++row)
    if (free_of[rows_.dof(row)] < 0) {
      const PetscInt global_row = row;
      petsc_check(MatSetValues(A, 1, &global_row, 1, &global_row, &diagonal_, INSERT_VALUES),
                  "MatSetValues");
    }
  report_rank_shares(rows_, seconds_since(start), phases_);
  petsc_check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  petsc_check(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  petsc_check(MatSetOption(A, MAT_SPD, PETSC_TRUE), "MatSetOption");
  if (!settings_.direct && settings_.block_size == 3 && !settings_.coordinates.empty())
    attach_rigid_body_modes(A, PETSC_COMM_WORLD, owned_coordinates(rows_, settings_.coordinates));
  const double assemble_seconds = seconds_since(start);

  petsc_check(KSPCreate(PETSC_COMM_WORLD, &petsc_->ksp), "KSPCreate");
  petsc_check(KSPSetOperators(petsc_->ksp, A, A), "KSPSetOperators");
  if (!settings_.direct) petsc_check(petsc_->progress.attach(petsc_->ksp), "KSPMonitorSet");
  configure_solver(petsc_->ksp, A, rows_, settings_, petsc_->p_multigrid);
  const auto setup_start = std::chrono::steady_clock::now();
  const PetscErrorCode setup = KSPSetUp(petsc_->ksp);
  if (setup != 0)
    throw InputError(settings_.where,
                     "the " + settings_.what + " matrix could not be " +
                         (settings_.direct ? "factorised (MUMPS): it is singular or not positive "
                                             "definite; the model is a mechanism or an element "
                                             "is degenerate"
                                           : "prepared for the multigrid solver (GAMG set-up "
                                             "failed)"));
  petsc_check(MatCreateVecs(A, &petsc_->x, &petsc_->b), "MatCreateVecs");
  petsc_check(VecDuplicate(petsc_->b, &petsc_->r), "VecDuplicate");
  petsc_check(VecScatterCreateToAll(petsc_->x, &petsc_->to_all, &petsc_->all),
              "VecScatterCreateToAll");
  const std::string solver = settings_.direct   ? "MUMPS"
                             : settings_.coarse ? "p-multigrid + GAMG"
                                                : "GAMG";
  phases_.info(format("distributed: %.0f rows on %.0f ranks, this rank's part assembled in %.2f s",
                      static_cast<double>(K.rows), static_cast<double>(rows_.size),
                      assemble_seconds) +
               ", " + solver + format(" set up in %.2f s", seconds_since(setup_start)));
}

DistributedSystem::~DistributedSystem() = default;

bool p_multigrid_requested() {
  PetscRuntime::ensure();
  PetscBool wanted = PETSC_TRUE;
  petsc_check(PetscOptionsGetBool(nullptr, "styk_", "-p_multigrid", &wanted, nullptr),
              "PetscOptionsGetBool");
  return wanted == PETSC_TRUE;
}

std::string DistributedSystem::description() const {
  const std::string ranks = " on " + std::to_string(rows_.size) + " MPI ranks";
  if (settings_.direct) return "MUMPS distributed Cholesky (PETSc)" + ranks;
  return std::string(settings_.coarse ? "PETSc CG + p-multigrid (quadratic to linear level) + "
                                      : "PETSc CG + ") +
         "GAMG (smoothed aggregation, rigid-body near-null space)" + ranks;
}

std::vector<double> DistributedSystem::solve(const std::vector<double>& f,
                                             const std::vector<double>& prescribed_value) {
  const auto start = std::chrono::steady_clock::now();
  double relative = 0.0;
  std::vector<double> u = solve_once(f, prescribed_value, &relative);
  if (!settings_.direct) return u;
  const std::string solved =
      format("MUMPS: solved in %.2f s, relative residual %.2g", seconds_since(start), relative);
  if (!settings_.refine) {
    phases_.info(solved);
    return u;
  }
  const RefinementOutcome refined = refine(f, u);
  phases_.info(solved + ", " + describe(refined));
  return u;
}

RefinementOutcome DistributedSystem::refine(const std::vector<double>& f, std::vector<double>& u) {
  // The residual of this rank's free rows (whole rows: the solve reads only the owner's rows of
  // its right-hand side); every rank holds the whole correction and x, so the stopping decisions
  // agree across ranks.
  const ExtendedResidual residual = [&](const std::vector<double>& x, std::vector<double>& r) {
    std::fill(r.begin(), r.end(), 0.0);
    for (std::size_t k = 0; k < kept_.dof.size(); ++k) {
      const int first = kept_.row_ptr[k];
      const int dof = kept_.dof[k];
      r[dof] = static_cast<double>(extended_row_residual(f[dof], kept_.col.data() + first,
                                                         kept_.values.data() + first,
                                                         kept_.row_ptr[k + 1] - first, x));
    }
  };
  const std::vector<double> zero(u.size(), 0.0);
  const Correction correct = [&](const std::vector<double>& r) {
    return solve_once(r, zero, nullptr);
  };
  return refine_in_extended_precision(u, residual, correct);
}

std::vector<double> DistributedSystem::solve_once(const std::vector<double>& f,
                                                  const std::vector<double>& prescribed_value,
                                                  double* relative_residual) {
  Vec b = petsc_->b, x = petsc_->x;
  petsc_check(VecSet(b, 0.0), "VecSet");
  const std::vector<int>& free_of = partition_.free_of_dof;
  // Each rank adds what it holds: the owner its rows of f and the prescribed rows' values, every
  // rank its part of -K_fp u_p.
  for (int row = rows_.begin(); row < rows_.end(); ++row) {
    const int dof = rows_.dof(row);
    const PetscScalar value = free_of[dof] >= 0 ? f[dof] : diagonal_ * prescribed_value[dof];
    const PetscInt index = row;
    petsc_check(VecSetValues(b, 1, &index, &value, ADD_VALUES), "VecSetValues");
  }
  for (const CouplingEntry& entry : coupling_) {
    const PetscScalar value = -entry.value * prescribed_value[entry.dof];
    if (value == 0.0) continue;
    const PetscInt index = rows_.row(entry.free_row);
    petsc_check(VecSetValues(b, 1, &index, &value, ADD_VALUES), "VecSetValues");
  }
  petsc_check(VecAssemblyBegin(b), "VecAssemblyBegin");
  petsc_check(VecAssemblyEnd(b), "VecAssemblyEnd");

  PetscReal b_norm = 0.0;
  petsc_check(VecNorm(b, NORM_2, &b_norm), "VecNorm");
  petsc_check(VecSet(x, 0.0), "VecSet");
  iterations_ = 0;
  if (b_norm > 0.0) {
    const auto start = std::chrono::steady_clock::now();
    petsc_->progress.start(b_norm);
    const PetscErrorCode code = KSPSolve(petsc_->ksp, b, x);
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    PetscInt its = 0;
    KSPGetConvergedReason(petsc_->ksp, &reason);
    KSPGetIterationNumber(petsc_->ksp, &its);
    iterations_ = settings_.direct ? 0 : static_cast<int>(its);
    if (code != 0 || reason < 0) {
      if (settings_.direct) throw singular_matrix(settings_);
      throw NotConvergedError(
          format("the iterative solver (CG + GAMG, distributed) did not converge: %.0f iterations "
                 "(PETSc reason %.0f)",
                 static_cast<double>(its), static_cast<double>(reason)));
    }
    // The true residual, whatever the solver.
    petsc_check(MatMult(petsc_->A, x, petsc_->r), "MatMult");
    petsc_check(VecAXPY(petsc_->r, -1.0, b), "VecAXPY");
    PetscReal r_norm = 0.0;
    petsc_check(VecNorm(petsc_->r, NORM_2, &r_norm), "VecNorm");
    const double relative = r_norm / b_norm;
    if (!(relative <= settings_.residual_limit))
      throw InputError(settings_.where,
                       "the " + settings_.what + " matrix is nearly singular: the distributed " +
                           format("solve left a relative residual of %.3g", relative));
    if (relative_residual != nullptr) *relative_residual = relative;
    if (!settings_.direct)
      phases_.info(format("CG + GAMG: %.0f iterations in %.2f s, relative residual %.2g",
                          static_cast<double>(its), seconds_since(start), relative));
  }
  std::vector<double> u(f.size());
  gather_to_every_rank(petsc_->to_all, petsc_->all, rows_, x, u.data(), u.size());
  for (int dof : partition_.prescribed) u[dof] = prescribed_value[dof];
  return u;
}

std::vector<double> DistributedSystem::solve_homogeneous(const std::vector<double>& F,
                                                         int columns) {
  const std::size_t n = columns > 0 ? F.size() / static_cast<std::size_t>(columns) : 0;
  std::vector<double> X(F.size(), 0.0);
  if (columns <= 0 || n == 0) return X;
  const PetscInt local = rows_.end() - rows_.begin();
  Mat B = nullptr, Y = nullptr;
  petsc_check(
      MatCreateDense(PETSC_COMM_WORLD, local, PETSC_DECIDE, PETSC_DETERMINE, columns, nullptr, &B),
      "MatCreateDense");
  PetscScalar* b = nullptr;
  PetscInt lda = 0;
  petsc_check(MatDenseGetLDA(B, &lda), "MatDenseGetLDA");
  petsc_check(MatDenseGetArrayWrite(B, &b), "MatDenseGetArrayWrite");
  // The owner's rows of F; prescribed rows are zero (their value, diagonal x 0).
  for (int row = rows_.begin(); row < rows_.end(); ++row) {
    const int dof = rows_.dof(row);
    const bool free = partition_.free_of_dof[dof] >= 0;
    for (int j = 0; j < columns; ++j)
      b[(row - rows_.begin()) + static_cast<std::size_t>(j) * lda] =
          free ? F[static_cast<std::size_t>(j) * n + dof] : 0.0;
  }
  petsc_check(MatDenseRestoreArrayWrite(B, &b), "MatDenseRestoreArrayWrite");
  petsc_check(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  petsc_check(MatDuplicate(B, MAT_DO_NOT_COPY_VALUES, &Y), "MatDuplicate");
  const PetscErrorCode code = KSPMatSolve(petsc_->ksp, B, Y);
  if (code != 0) {
    MatDestroy(&Y);
    MatDestroy(&B);
    throw singular_matrix(settings_);
  }
  // Every rank gets every column: scattered column by column as solve() scatters x.
  for (int j = 0; j < columns; ++j) {
    Vec y = nullptr;
    double* column = X.data() + static_cast<std::size_t>(j) * n;
    petsc_check(MatDenseGetColumnVecRead(Y, j, &y), "MatDenseGetColumnVecRead");
    gather_to_every_rank(petsc_->to_all, petsc_->all, rows_, y, column, n);
    petsc_check(MatDenseRestoreColumnVecRead(Y, j, &y), "MatDenseRestoreColumnVecRead");
    for (int dof : partition_.prescribed) column[dof] = 0.0;
  }
  MatDestroy(&Y);
  MatDestroy(&B);
  return X;
}

}  // namespace styk::solver_detail
