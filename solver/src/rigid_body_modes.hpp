// GAMG's near-null space for elasticity: the six rigid-body modes of the nodes' coordinates,
// attached to a matrix with 3 dofs per node (serial and distributed solvers, the p-multigrid's
// coarse level).
#pragma once

#include <petscmat.h>

#include <vector>

namespace styk::solver_detail {

// `local_xyz`: the coordinates of the nodes whose rows this process owns, 3 per node in row order.
void attach_rigid_body_modes(Mat M, MPI_Comm comm, const std::vector<double>& local_xyz);

}  // namespace styk::solver_detail
