// PETSc (and with it MPI) can be initialised only once per process and never again after
// finalising, so the runtime lives from first use to process exit. It is set up without any
// command-line arguments (PETSc must not read ours), without PETSc's signal handler (ours stays in
// charge) and with errors returned as codes, which petsc_check() turns into exceptions.
#pragma once

#include <petscsys.h>

#include <stdexcept>
#include <string>

namespace styk::solver_detail {

class PetscRuntime {
 public:
  // Initialises PETSc on first call; cheap afterwards. Throws std::runtime_error on failure.
  static void ensure() { static const PetscRuntime runtime; }

  PetscRuntime(const PetscRuntime&) = delete;
  PetscRuntime& operator=(const PetscRuntime&) = delete;

 private:
  PetscRuntime() {
    PetscBool initialized = PETSC_FALSE;
    PetscInitialized(&initialized);
    if (initialized) return;  // someone else (e.g. an embedding program) owns PETSc
    PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
    PetscOptionsSetValue(nullptr, "-skip_petscrc", nullptr);
    if (PetscInitializeNoArguments() != 0) throw std::runtime_error("PETSc failed to initialise");
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    owns_ = true;
  }
  ~PetscRuntime() {
    if (owns_) PetscFinalize();
  }

  bool owns_ = false;
};

inline void petsc_check(PetscErrorCode code, const char* call) {
  if (code != 0)
    throw std::runtime_error(std::string("PETSc error ") + std::to_string(static_cast<int>(code)) +
                             " in " + call);
}

}  // namespace styk::solver_detail
