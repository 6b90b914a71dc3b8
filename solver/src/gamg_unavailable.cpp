// Built when STYK_PETSC is off: there is no iterative solver.
#include "linear_solver.hpp"

namespace styk::solver_detail {

std::unique_ptr<LinearSolver> make_gamg_solver(const SolverContext&, double) { return nullptr; }

}  // namespace styk::solver_detail
