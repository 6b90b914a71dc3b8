#include "p_multigrid.hpp"

#include <vector>

#include "petsc_runtime.hpp"

namespace styk::solver_detail {
namespace {

// P = P_node (x) I_3: dof 3a + c takes w_j times coarse dof 3 j + c.
Mat interpolation(const LinearCoarseSpace& space, PetscInt fine_rows) {
  const PetscInt coarse_rows = 3 * static_cast<PetscInt>(space.coarse_nodes);
  std::vector<PetscInt> per_row(fine_rows);
  for (PetscInt row = 0; row < fine_rows; ++row)
    per_row[row] = space.ptr[row / 3 + 1] - space.ptr[row / 3];
  Mat P = nullptr;
  petsc_check(MatCreateSeqAIJ(PETSC_COMM_SELF, fine_rows, coarse_rows, 0, per_row.data(), &P),
              "MatCreateSeqAIJ");
  for (PetscInt row = 0; row < fine_rows; ++row) {
    const int a = static_cast<int>(row / 3), c = static_cast<int>(row % 3);
    for (int p = space.ptr[a]; p < space.ptr[a + 1]; ++p) {
      const PetscInt column = 3 * static_cast<PetscInt>(space.node[p]) + c;
      const PetscScalar w = space.weight[p];
      petsc_check(MatSetValues(P, 1, &row, 1, &column, &w, INSERT_VALUES), "MatSetValues");
    }
  }
  petsc_check(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  petsc_check(MatSetBlockSizes(P, 3, 3), "MatSetBlockSizes");
  return P;
}

void attach_rigid_body_modes(Mat coarse, const std::vector<double>& xyz) {
  Vec coordinates = nullptr;
  petsc_check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(xyz.size()), &coordinates),
              "VecCreateSeq");
  VecSetBlockSize(coordinates, 3);
  PetscScalar* values = nullptr;
  VecGetArray(coordinates, &values);
  std::copy(xyz.begin(), xyz.end(), values);
  VecRestoreArray(coordinates, &values);
  MatNullSpace modes = nullptr;
  PetscErrorCode code = MatNullSpaceCreateRigidBody(coordinates, &modes);
  if (code == 0) code = MatSetNearNullSpace(coarse, modes);
  MatNullSpaceDestroy(&modes);
  VecDestroy(&coordinates);
  petsc_check(code, "MatNullSpaceCreateRigidBody");
}

}  // namespace

PMultigrid::~PMultigrid() {
  MatDestroy(&coarse_);
  MatDestroy(&P_);
}

void PMultigrid::configure(PC pc, Mat A, const LinearCoarseSpace& space,
                           const std::vector<double>& corner_xyz, PetscReal threshold) {
  PetscInt fine_rows = 0;
  petsc_check(MatGetSize(A, &fine_rows, nullptr), "MatGetSize");
  P_ = interpolation(space, fine_rows);
  petsc_check(MatPtAP(A, P_, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &coarse_), "MatPtAP");
  petsc_check(MatSetBlockSize(coarse_, 3), "MatSetBlockSize");
  attach_rigid_body_modes(coarse_, corner_xyz);
  coarse_rows_ = 3 * static_cast<PetscInt>(space.coarse_nodes);

  petsc_check(PCSetType(pc, PCMG), "PCSetType");
  petsc_check(PCMGSetLevels(pc, 2, nullptr), "PCMGSetLevels");
  petsc_check(PCMGSetGalerkin(pc, PC_MG_GALERKIN_NONE), "PCMGSetGalerkin");
  petsc_check(PCMGSetInterpolation(pc, 1, P_), "PCMGSetInterpolation");
  // Fine level: Chebyshev over Jacobi, eigenvalue bounds estimated as GAMG's levels do.
  KSP smoother = nullptr;
  petsc_check(PCMGGetSmoother(pc, 1, &smoother), "PCMGGetSmoother");
  petsc_check(KSPSetType(smoother, KSPCHEBYSHEV), "KSPSetType");
  petsc_check(KSPChebyshevEstEigSet(smoother, 0.0, 0.1, 0.0, 1.1), "KSPChebyshevEstEigSet");
  petsc_check(KSPSetTolerances(smoother, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 2),
              "KSPSetTolerances");
  PC jacobi = nullptr;
  petsc_check(KSPGetPC(smoother, &jacobi), "KSPGetPC");
  petsc_check(PCSetType(jacobi, PCJACOBI), "PCSetType");
  // Coarse level: one GAMG V-cycle on P^T A P.
  petsc_check(PCMGGetCoarseSolve(pc, &coarse_solve_), "PCMGGetCoarseSolve");
  petsc_check(KSPSetOperators(coarse_solve_, coarse_, coarse_), "KSPSetOperators");
  petsc_check(KSPSetType(coarse_solve_, KSPPREONLY), "KSPSetType");
  PC gamg = nullptr;
  petsc_check(KSPGetPC(coarse_solve_, &gamg), "KSPGetPC");
  petsc_check(PCSetType(gamg, PCGAMG), "PCSetType");
  petsc_check(PCGAMGSetType(gamg, PCGAMGAGG), "PCGAMGSetType");
  petsc_check(PCGAMGSetNSmooths(gamg, 1), "PCGAMGSetNSmooths");
  PetscReal thresholds[] = {threshold};
  petsc_check(PCGAMGSetThreshold(gamg, thresholds, 1), "PCGAMGSetThreshold");
}

PetscInt PMultigrid::gamg_levels() const {
  if (!coarse_solve_) return 0;
  PC gamg = nullptr;
  KSPGetPC(coarse_solve_, &gamg);
  PetscInt levels = 0;
  PCMGGetLevels(gamg, &levels);
  return levels;
}

}  // namespace styk::solver_detail
