// Iterative solver for large models: PETSc CG preconditioned by GAMG (smoothed aggregation with
// the six rigid-body modes as near-null space, 3x3 node blocks). All active dofs stay in the
// system; prescribed dofs are eliminated symmetrically in place (rows and columns zeroed, diagonal
// set to the mean free diagonal so the spectrum is not distorted) and PETSc wraps the assembled
// CSR arrays without copying them.
#include <petscksp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "distributed_system.hpp"
#include "ksp_progress.hpp"
#include "linear_coarse_space.hpp"
#include "linear_solver.hpp"
#include "p_multigrid.hpp"
#include "parallel.hpp"
#include "petsc_runtime.hpp"
#include "rigid_body_modes.hpp"

namespace styk::solver_detail {
namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

class PetscMat {
 public:
  ~PetscMat() { MatDestroy(&mat_); }
  Mat* out() { return &mat_; }
  Mat get() const { return mat_; }

 private:
  Mat mat_ = nullptr;
};

class PetscVec {
 public:
  ~PetscVec() { VecDestroy(&vec_); }
  Vec* out() { return &vec_; }
  Vec get() const { return vec_; }

 private:
  Vec vec_ = nullptr;
};

class PetscKsp {
 public:
  ~PetscKsp() { KSPDestroy(&ksp_); }
  KSP* out() { return &ksp_; }
  KSP get() const { return ksp_; }

 private:
  KSP ksp_ = nullptr;
};

class GamgSolver final : public LinearSolver {
 public:
  GamgSolver(const SolverContext& context, double tolerance)
      : context_(context), tolerance_(tolerance), progress_(context_.phases) {
    PetscRuntime::ensure();
  }

  std::string description() const override {
    return p_multigrid_.coarse_rows() > 0
               ? "PETSc CG + p-multigrid (quadratic to linear level) + GAMG (smoothed "
                 "aggregation, rigid-body near-null space)"
               : "PETSc CG + GAMG (smoothed aggregation, rigid-body near-null space)";
  }

  void prepare(StiffnessMatrix& K, const DofPartition& partition) override {
    // The node-block product and the rigid-body near-null space below assume 3 dofs per node;
    // the analysis never picks this solver for a model with rotations (choose_solver).
    if (context_.prepared.has_rotations())
      throw std::logic_error("the GAMG solver was asked to solve a model with rotational dofs");
    const PhaseRecorder::Scope phase(context_.phases, "factorise");
    partition_ = partition;
    coupling_ = extract_coupling(K, partition);
    eliminate_prescribed(K);
    const PetscInt n = K.rows();
    petsc_check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, n, n, K.row_ptr().data(), K.col().data(),
                                          K.values().data(), A_.out()),
                "MatCreateSeqAIJWithArrays");
    petsc_check(MatSetBlockSize(A_.get(), 3), "MatSetBlockSize");
    std::vector<double> xyz;
    xyz.reserve(n);
    for (int a = 0; a < context_.prepared.active_nodes(); ++a)
      for (int d = 0; d < 3; ++d)
        xyz.push_back(context_.model.coords[context_.prepared.node_of_active[a]][d]);
    attach_rigid_body_modes(A_.get(), PETSC_COMM_SELF, xyz);
    petsc_check(KSPCreate(PETSC_COMM_SELF, ksp_.out()), "KSPCreate");
    KSP ksp = ksp_.get();
    // Tuning from the environment goes through this prefix (PETSC_OPTIONS="-styk_pc_gamg_...").
    petsc_check(KSPSetOptionsPrefix(ksp, "styk_"), "KSPSetOptionsPrefix");
    // PETSc's own product (I-node kernel over the node rows) serves CG and the smoothers: it
    // measured faster on one core than a threaded shell product over the same arrays on two
    // (bench/README.md, "The serial CG + GAMG product").
    petsc_check(KSPSetOperators(ksp, A_.get(), A_.get()), "KSPSetOperators");
    petsc_check(KSPSetType(ksp, KSPCG), "KSPSetType");
    // Stop on the true (unpreconditioned) relative residual, the quantity the tolerance names.
    petsc_check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    petsc_check(KSPSetTolerances(ksp, tolerance_, 0.0, PETSC_DEFAULT, kMaxIterations),
                "KSPSetTolerances");
    PC pc = nullptr;
    petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
    const std::optional<LinearCoarseSpace> coarse =
        p_multigrid_requested() ? linear_coarse_space(context_.model, context_.prepared)
                                : std::nullopt;
    if (coarse)
      p_multigrid_.configure(pc, A_.get(), *coarse, corner_coordinates(*coarse), kThreshold);
    else
      configure_gamg(pc);
    petsc_check(progress_.attach(ksp), "KSPMonitorSet");
    petsc_check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
    petsc_check(KSPSetUp(ksp), "KSPSetUp (GAMG set-up)");
    report_hierarchy(pc, n, coarse.has_value());
  }

  std::vector<double> solve(const std::vector<double>& f,
                            const std::vector<double>& prescribed_value) override {
    const PhaseRecorder::Scope phase(context_.phases, "solve");
    const std::vector<double> rhs_free = free_rhs(f, partition_, coupling_, prescribed_value);
    std::vector<double> rhs(f.size());
    for (int i = 0; i < partition_.free_count(); ++i) rhs[partition_.free_dofs[i]] = rhs_free[i];
    for (int dof : partition_.prescribed) rhs[dof] = diagonal_ * prescribed_value[dof];
    std::vector<double> u(f.size(), 0.0);

    const PetscInt n = static_cast<PetscInt>(f.size());
    PetscVec b, x, r;
    petsc_check(VecCreateSeqWithArray(PETSC_COMM_SELF, 3, n, rhs.data(), b.out()), "VecCreate");
    petsc_check(VecCreateSeqWithArray(PETSC_COMM_SELF, 3, n, u.data(), x.out()), "VecCreate");
    PetscReal b_norm = 0.0;
    petsc_check(VecNorm(b.get(), NORM_2, &b_norm), "VecNorm");
    iterations_ = 0;
    if (b_norm > 0.0) {
      const auto start = std::chrono::steady_clock::now();
      progress_.start(b_norm);
      petsc_check(KSPSolve(ksp_.get(), b.get(), x.get()), "KSPSolve");
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      KSPConvergedReason reason;
      PetscReal residual = 0.0;
      PetscInt its = 0;
      KSPGetConvergedReason(ksp_.get(), &reason);
      KSPGetIterationNumber(ksp_.get(), &its);
      KSPGetResidualNorm(ksp_.get(), &residual);
      iterations_ = static_cast<int>(its);
      if (reason < 0)
        throw NotConvergedError(
            format("the iterative solver (CG + GAMG) did not converge: %.0f iterations, relative "
                   "residual %.3g (PETSc reason %.0f)",
                   static_cast<double>(its), residual / b_norm, static_cast<double>(reason)));
      // Check the true residual, not CG's recursively updated one.
      petsc_check(VecDuplicate(b.get(), r.out()), "VecDuplicate");
      petsc_check(MatMult(A_.get(), x.get(), r.get()), "MatMult");
      petsc_check(VecAXPY(r.get(), -1.0, b.get()), "VecAXPY");
      PetscReal r_norm = 0.0;
      petsc_check(VecNorm(r.get(), NORM_2, &r_norm), "VecNorm");
      const double relative = r_norm / b_norm;
      if (!(relative <= std::max(1e-6, 10.0 * tolerance_)))
        throw NotConvergedError(format(
            "the iterative solver stopped after %.0f iterations with a true relative residual "
            "of %.3g: the stiffness matrix is nearly singular (a mechanism or badly "
            "distorted elements?)",
            static_cast<double>(its), relative));
      context_.phases.info(format("CG + GAMG: %.0f iterations in %.2f s, relative residual %.2g",
                                  static_cast<double>(its), seconds, relative));
    }
    for (int dof : partition_.prescribed) u[dof] = prescribed_value[dof];
    return u;
  }

  int iterations() const override { return iterations_; }

 private:
  static constexpr PetscInt kMaxIterations = 5000;
  // Drop weak graph edges (relative) when aggregating; 0.01-0.05 is the usual range for
  // elasticity, chosen by measurement on the cantilever.
  static constexpr PetscReal kThreshold = 0.01;

  // Zero prescribed rows and columns; the diagonal of a prescribed row becomes the mean diagonal
  // of the free rows. The coupling K_fp has been saved for the right-hand side before.
  void eliminate_prescribed(StiffnessMatrix& K) {
    const std::vector<int>& row_ptr = K.row_ptr();
    const std::vector<int>& col = K.col();
    std::vector<double>& values = K.values();
    const std::vector<int>& free_of_dof = partition_.free_of_dof;
    double diagonal_sum = 0.0;
    for (int dof : partition_.free_dofs)
      for (int p = row_ptr[dof]; p < row_ptr[dof + 1]; ++p)
        if (col[p] == dof) diagonal_sum += values[p];
    diagonal_ = partition_.free_count() > 0 ? diagonal_sum / partition_.free_count() : 1.0;
    parallel_for(K.rows(), context_.threads, 4096, [&](int begin, int end, int) {
      for (int row = begin; row < end; ++row) {
        const bool row_prescribed = free_of_dof[row] < 0;
        for (int p = row_ptr[row]; p < row_ptr[row + 1]; ++p) {
          if (row_prescribed)
            values[p] = col[p] == row ? diagonal_ : 0.0;
          else if (free_of_dof[col[p]] < 0)
            values[p] = 0.0;
        }
      }
    });
    K.set_pristine(false);
  }

  void configure_gamg(PC pc) {
    petsc_check(PCSetType(pc, PCGAMG), "PCSetType");
    petsc_check(PCGAMGSetType(pc, PCGAMGAGG), "PCGAMGSetType");
    petsc_check(PCGAMGSetNSmooths(pc, 1), "PCGAMGSetNSmooths");
    PetscReal threshold[] = {kThreshold};
    petsc_check(PCGAMGSetThreshold(pc, threshold, 1), "PCGAMGSetThreshold");
  }

  void report_hierarchy(PC pc, PetscInt n, bool p_multigrid) const {
    if (p_multigrid) {
      context_.phases.info(
          format("p-multigrid: %.0f dofs, linear coarse level of %.0f dofs, GAMG below it with "
                 "%.0f levels",
                 static_cast<double>(n), static_cast<double>(p_multigrid_.coarse_rows()),
                 static_cast<double>(p_multigrid_.gamg_levels())));
      return;
    }
    PetscInt levels = 0;
    PCMGGetLevels(pc, &levels);
    context_.phases.info(format("GAMG: %.0f dofs, %.0f levels", static_cast<double>(n),
                                static_cast<double>(levels)));
  }

  std::vector<double> corner_coordinates(const LinearCoarseSpace& space) const {
    std::vector<double> xyz;
    xyz.reserve(3 * space.corner_node.size());
    for (int a : space.corner_node)
      for (int d = 0; d < 3; ++d)
        xyz.push_back(context_.model.coords[context_.prepared.node_of_active[a]][d]);
    return xyz;
  }

  SolverContext context_;
  double tolerance_;
  KspProgress progress_;
  PetscMat A_;              // wraps the StiffnessMatrix arrays; destroyed before them by contract
  PMultigrid p_multigrid_;  // the interpolation and coarse operator the KSP's PC refers to
  PetscKsp ksp_;
  DofPartition partition_;
  std::vector<CouplingEntry> coupling_;
  double diagonal_ = 1.0;
  int iterations_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_gamg_solver(const SolverContext& context, double tolerance) {
  return std::make_unique<GamgSolver>(context, tolerance);
}

}  // namespace styk::solver_detail
