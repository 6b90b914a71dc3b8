// Built when STYK_PETSC is off: there is no distributed solver (join_mpi_world refuses first).
#include <stdexcept>

#include "distributed_system.hpp"

namespace styk::solver_detail {

struct DistributedSystem::Petsc {};

DistributedSystem::DistributedSystem(const RankRows& rows, const CsrView&,
                                     const DofPartition& partition, DistributedSettings settings,
                                     const PhaseRecorder& phases)
    : rows_(rows), partition_(partition), settings_(std::move(settings)), phases_(phases) {
  throw std::runtime_error("this build has no PETSc/MPI and cannot solve distributed");
}

DistributedSystem::~DistributedSystem() = default;

std::vector<double> DistributedSystem::solve(const std::vector<double>&,
                                             const std::vector<double>&) {
  throw std::runtime_error("this build has no PETSc/MPI and cannot solve distributed");
}

std::vector<double> DistributedSystem::solve_homogeneous(const std::vector<double>&, int) {
  throw std::runtime_error("this build has no PETSc/MPI and cannot solve distributed");
}

std::string DistributedSystem::description() const { return "unavailable"; }

bool p_multigrid_requested() { return false; }

}  // namespace styk::solver_detail
