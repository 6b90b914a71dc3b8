// Per-iteration progress of PETSc's CG (serial and distributed): every few iterations an info line
// "CG iteration 20: relative residual 3.1e-05 after 1.24 s" (the CLI's stderr, the GUI's log),
// so a long solve shows that it advances and how fast.
#pragma once

#include <petscksp.h>

#include <chrono>
#include <cstdio>

#include "phase_recorder.hpp"

namespace styk::solver_detail {

class KspProgress {
 public:
  explicit KspProgress(const PhaseRecorder& phases, int every = 10)
      : phases_(phases), every_(every) {}

  // Installs the monitor on `ksp`; this object must outlive the KSP's solves.
  PetscErrorCode attach(KSP ksp) {
    return KSPMonitorSet(ksp, &KspProgress::monitor, this, nullptr);
  }

  // Call before each solve: the norm relative residuals are measured against.
  void start(double rhs_norm) {
    rhs_norm_ = rhs_norm > 0.0 ? rhs_norm : 1.0;
    start_ = std::chrono::steady_clock::now();
  }

 private:
  static PetscErrorCode monitor(KSP, PetscInt iteration, PetscReal residual, void* context) {
    auto* self = static_cast<KspProgress*>(context);
    if (iteration == 0 || iteration % self->every_ != 0) return 0;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - self->start_).count();
    char line[160];
    std::snprintf(line, sizeof line, "CG iteration %d: relative residual %.2e after %.2f s",
                  static_cast<int>(iteration), residual / self->rhs_norm_, seconds);
    self->phases_.info(line);
    return 0;
  }

  const PhaseRecorder& phases_;
  int every_;
  double rhs_norm_ = 1.0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace styk::solver_detail
