// Linear static analysis: validates a Model, assembles the stiffness over its TElements, solves
// each *STEP (CHOLMOD supernodal Cholesky or PETSc CG + GAMG) and recovers displacements,
// reactions, strains and stresses. No Eigen, CHOLMOD or PETSc types in this header.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk {

struct PhaseTiming {
  std::string phase;
  double seconds = 0.0;
};

// Receives progress of a long analysis. The CLI prints these to stderr; a GUI shows a progress bar.
class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  virtual void begin(const std::string& phase) = 0;  // e.g. "assemble"
  virtual void end(const std::string& phase, double seconds) = 0;
  virtual void info(const std::string& message) = 0;  // one line of detail
  // A solvable model whose answer is likely poor (locking, hourglassing, distortion): shown even
  // where detail lines are not.
  virtual void warning(const std::string& message) { info("warning: " + message); }
};

enum class ContactSolveKind { Automatic, Dense, Sparse };

struct SolveOptions {
  int threads = 0;  // worker threads for assembly and recovery; 0 = hardware_concurrency
  // Overrides *STATIC, SOLVER= of the deck unless Automatic.
  LinearSolverKind force = LinearSolverKind::Automatic;
  // Relative residual ||K u - f|| / ||f|| at which CG stops (iterative solver only). Measured on
  // the 51k-dof C3D20 cantilever against CHOLMOD: 1e-6 -> displacements within 5e-10 and
  // stresses within 7e-9 of the direct solution (53 iterations); 1e-7 -> 1e-10 / 9e-10 (59);
  // 1e-9 -> 4e-12 (72). 1e-7 keeps three orders of margin on the ~1e-6 goal on finer meshes.
  double iterative_tolerance = 1e-7;
  // The most memory (GB) the direct solver's factor may take, judged from the symbolic analysis
  // before factorising; 0 = 80 % of the machine's physical memory. Above it the automatic choice
  // switches to the iterative solver and a forced direct solve stops with the estimate.
  double memory_limit_gb = 0.0;
  // Solve across the ranks of the MPI world this process belongs to (mpi_world.hpp): every rank
  // runs the same analysis with the same options, assembles its own elements and takes part in
  // one distributed linear solve (MUMPS where the serial rule picks CHOLMOD, CG + GAMG where it
  // picks GAMG); every rank ends with the whole results. docs/solver.md "Distributed runs".
  bool distributed = false;
  // How the contact iteration sees the structure (docs/contact.md, "Sparse contact solve"):
  // Dense holds the compliance S over the contact rows, Sparse solves each Newton step as one
  // sparse LU of K with the contact rows, Automatic picks Sparse when S would take more than a
  // quarter of the memory limit or a sparse step is expected to cost less than a dense one
  // (solver/src/contact_solve_choice.hpp). Serial runs only (distributed: dense).
  ContactSolveKind contact_solve = ContactSolveKind::Automatic;
};

struct AnalysisReport {
  std::vector<PhaseTiming> timings;   // in the order the phases ran (repeated per step if redone)
  std::string linear_solver;          // e.g. "CHOLMOD supernodal (METIS node-graph ordering)"
  long long dofs = 0;                 // unknowns of the (first) linear system solved
  int iterations = 0;                 // CG iterations summed over the steps (iterative solver)
  std::vector<std::string> warnings;  // what the model checks found (model_warnings), in order
};

// Runs every step of `model` as a linear static step (one increment each). Throws InputError for
// a model that cannot be analysed (missing sections/materials, unknown element types, loads on
// unused nodes, mechanisms, singular stiffness), NotConvergedError if the iterative solver fails.
// `progress` and `report` may be null.
Results run_static_analysis(const Model& model, const ElementRegistry& registry,
                            const SolveOptions& options, ProgressSink* progress,
                            AnalysisReport* report);

}  // namespace styk
