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
  RankRows rows;                        // the rows (active dofs) this rank owns
  std::vector<char> assembles_element;  // per element: assembled by this rank
  long long cut_node_pairs = 0;         // node pairs of the graph coupling two ranks
};

// Rows shared by a graph partition of `graph` (rank_partition.hpp). A rank assembles every element
// touching a node whose rows it needs whole: its own, and the nodes of `rows_every_rank_needs`
// (the equations' dependent dofs, whose rows the elimination spreads into their masters' and
// neighbours' rows). The elements along the cut are assembled by both ranks, and each owned row
// is summed over the same elements in the same order as serially (assemble_stiffness): the
// distributed matrix is the serial one bit for bit, with no exchange of partial sums.
RankShare share_of_rank(const Model& model, const PreparedModel& prepared, const NodeGraph& graph,
                        const MpiWorld& world, const std::vector<int>& rows_every_rank_needs);

// `direct`: MUMPS Cholesky, otherwise CG + GAMG with `tolerance`. prepare() takes K assembled from
// the rank's share of elements (RankShare::assembles_element, *TRANSFORM/*EQUATION applied), whose
// owned rows are whole; other rows are not read. Throws std::runtime_error in a build without
// PETSc.
std::unique_ptr<LinearSolver> make_distributed_solver(const SolverContext& context,
                                                      const RankRows& rows, bool direct,
                                                      double tolerance);

}  // namespace styk::solver_detail
