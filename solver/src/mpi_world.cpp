#include "styk/solver/mpi_world.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

#ifdef STYK_HAVE_PETSC
#include "petsc_runtime.hpp"
#endif

namespace styk {
namespace {

int environment_int(const char* name, int fallback) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return fallback;
  return std::atoi(value);
}

}  // namespace

bool started_by_mpi_runner() {
  // Open MPI sets OMPI_COMM_WORLD_SIZE, MPICH's Hydra PMI_SIZE, PMIx-based runners PMIX_RANK.
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr ||
         std::getenv("PMIX_RANK") != nullptr;
}

int mpi_ranks_on_this_machine() {
  const int local =
      environment_int("OMPI_COMM_WORLD_LOCAL_SIZE", environment_int("MPI_LOCALNRANKS", 1));
  return local > 0 ? local : 1;
}

#ifdef STYK_HAVE_PETSC

MpiWorld join_mpi_world() {
  solver_detail::PetscRuntime::ensure();
  MpiWorld world;
  MPI_Comm_rank(PETSC_COMM_WORLD, &world.rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &world.size);
  return world;
}

void abort_mpi_world(int code) {
  MPI_Abort(PETSC_COMM_WORLD, code);
  std::_Exit(code);  // MPI_Abort does not return; this keeps [[noreturn]] honest
}

#else

MpiWorld join_mpi_world() {
  throw std::runtime_error(
      "this build has no PETSc/MPI (configure with STYK_PETSC=ON) and cannot run distributed");
}

void abort_mpi_world(int code) { std::_Exit(code); }

#endif

}  // namespace styk
