// The MPI world of a distributed run (`mpirun -n N styk solve ...`, docs/solver.md "Distributed
// runs"). Every rank reads the deck and runs the same analysis; the linear systems are assembled
// from each rank's elements into one PETSc MPI matrix and solved across the ranks. No MPI or PETSc
// types in this header.
#pragma once

namespace styk {

struct MpiWorld {
  int rank = 0;
  int size = 1;
};

// True when an MPI runner (Open MPI's or MPICH's mpirun/mpiexec) started this process as one of
// its ranks: read from the environment the runner sets, without initialising MPI.
bool started_by_mpi_runner();

// Ranks the runner placed on this machine (to share its cores between them); 1 when unknown.
int mpi_ranks_on_this_machine();

// Joins the MPI world (initialising MPI through PETSc on first call). Throws std::runtime_error
// when this build has no PETSc/MPI or MPI fails to initialise.
MpiWorld join_mpi_world();

// Ends every rank of the world with `code` (a rank that failed alone must not leave the others
// waiting in a collective operation).
[[noreturn]] void abort_mpi_world(int code);

}  // namespace styk
