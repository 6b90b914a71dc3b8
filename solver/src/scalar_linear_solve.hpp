// The linear solve of the steady scalar-field driver: K phi = f + r with phi prescribed at some
// unknowns (r: the reaction flows there). Serial CHOLMOD or distributed MUMPS.
#pragma once

#include <map>
#include <memory>
#include <string>

#include <Eigen/SparseCore>

#include "phase_recorder.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/solver/mpi_world.hpp"

namespace styk::solver_detail {

class ScalarLinearSolve {
 public:
  virtual ~ScalarLinearSolve() = default;
  virtual int free_count() const = 0;
  // True when `prescribed` names exactly the unknowns this solve was prepared for.
  virtual bool same_partition(const std::map<int, double>& prescribed) const = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& f, const std::map<int, double>& prescribed,
                                const SourceLoc& where) = 0;
  virtual std::string description() const = 0;
};

// Across the ranks of `world`: every rank holds the whole conductance K and adds the rows it owns.
std::unique_ptr<ScalarLinearSolve> make_distributed_scalar_solve(
    const Eigen::SparseMatrix<double>& K, const std::map<int, double>& prescribed,
    const SourceLoc& where, const MpiWorld& world, const PhaseRecorder& phases);

}  // namespace styk::solver_detail
