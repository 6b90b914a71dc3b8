// The p-multigrid preconditioner of the serial iterative solver for quadratic solids: a two-level
// PCMG whose fine level is the assembled quadratic stiffness A smoothed by Chebyshev-Jacobi, and
// whose coarse level is the Galerkin operator P^T A P on the linear coarse space
// (linear_coarse_space.hpp), solved by one GAMG V-cycle (smoothed aggregation, rigid-body modes of
// the corner nodes). PETSc types stay in the .cpp files that include petscksp.h.
#pragma once

#include <petscksp.h>

#include <vector>

#include "distributed_system.hpp"
#include "linear_coarse_space.hpp"

namespace styk::solver_detail {

// Owns the interpolation and the coarse operator the PC refers to (destroy after the KSP).
class PMultigrid {
 public:
  PMultigrid() = default;
  ~PMultigrid();
  PMultigrid(const PMultigrid&) = delete;
  PMultigrid& operator=(const PMultigrid&) = delete;

  // Makes `pc` (of a KSP whose operator is A, block size 3, 3 dofs per active node) the two-level
  // p-multigrid. `corner_xyz`: 3 coordinates per coarse node of `space`. `rows`: the ranks' PETSc
  // rows of A (distributed runs; each coarse node then belongs to the rank owning its corner's
  // rows); nullptr: one process, row = dof. GAMG's threshold as the plain solver's.
  void configure(PC pc, Mat A, const LinearCoarseSpace& space,
                 const std::vector<double>& corner_xyz, PetscReal threshold,
                 const RankRows* rows = nullptr);
  PetscInt coarse_rows() const { return coarse_rows_; }
  // The GAMG levels below the linear level (after the KSP's set-up).
  PetscInt gamg_levels() const;

 private:
  Mat P_ = nullptr;
  Mat coarse_ = nullptr;
  KSP coarse_solve_ = nullptr;  // owned by the PC
  PetscInt coarse_rows_ = 0;
};

}  // namespace styk::solver_detail
