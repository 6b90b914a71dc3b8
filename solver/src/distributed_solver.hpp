// The distributed side of the step drivers: which rows and elements are this rank's, and the
// LinearSolver that solves across the ranks (MUMPS or CG + GAMG over PETSc MPI matrices).
#pragma once

#include <memory>
#include <vector>

#include "distributed_system.hpp"
#include "linear_solver.hpp"
#include "stiffness_matrix.hpp"
#include "styk/solver/mpi_world.hpp"

namespace styk::solver_detail {

struct RankShare {
  RankRows rows;                   // the rows (active dofs) this rank owns
  std::vector<char> owns_element;  // per element: assembled by this rank
  long long cut_node_pairs = 0;    // node pairs of the graph coupling two ranks
};

// Rows shared by a graph partition of `graph` (rank_partition.hpp); an element belongs to the
// rank owning its first active node.
RankShare share_of_rank(const Model& model, const PreparedModel& prepared, const NodeGraph& graph,
                        const MpiWorld& world);

// `direct`: MUMPS Cholesky, otherwise CG + GAMG with `tolerance`. prepare() takes K holding this
// rank's part only (its own elements, *TRANSFORM/*EQUATION applied). Throws std::runtime_error in
// a build without PETSc.
std::unique_ptr<LinearSolver> make_distributed_solver(const SolverContext& context,
                                                      const RankRows& rows, bool direct,
                                                      double tolerance);

}  // namespace styk::solver_detail
