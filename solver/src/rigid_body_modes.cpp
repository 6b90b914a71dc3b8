#include "rigid_body_modes.hpp"

#include <algorithm>

#include "petsc_runtime.hpp"

namespace styk::solver_detail {

void attach_rigid_body_modes(Mat M, MPI_Comm comm, const std::vector<double>& local_xyz) {
  Vec coordinates = nullptr;
  petsc_check(
      VecCreateMPI(comm, static_cast<PetscInt>(local_xyz.size()), PETSC_DETERMINE, &coordinates),
      "VecCreateMPI");
  PetscErrorCode code = VecSetBlockSize(coordinates, 3);
  PetscScalar* values = nullptr;
  if (code == 0) code = VecGetArray(coordinates, &values);
  if (code == 0) {
    std::copy(local_xyz.begin(), local_xyz.end(), values);
    code = VecRestoreArray(coordinates, &values);
  }
  MatNullSpace modes = nullptr;
  if (code == 0) code = MatNullSpaceCreateRigidBody(coordinates, &modes);
  if (code == 0) code = MatSetNearNullSpace(M, modes);
  MatNullSpaceDestroy(&modes);
  VecDestroy(&coordinates);
  petsc_check(code, "MatNullSpaceCreateRigidBody");
}

}  // namespace styk::solver_detail
