// styk_solver_bench NX NY NZ [auto|cholmod|gamg|compare] [tolerance] [threads]
// Solves the PERFORMANCE.md C3D20 cantilever (10 x 1 x 1, E = 210000, nu = 0.3, clamped at x = 0,
// unit tip shear) and prints the phase timings, the solver and the tip deflection. Run it under
// `/usr/bin/time -v` for the peak memory. `compare` solves with CHOLMOD and with CG + GAMG at the
// given tolerance and prints the largest displacement difference relative to the largest
// displacement.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cantilever_model.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/solver/analysis.hpp"

namespace {

class StderrProgress final : public styk::ProgressSink {
 public:
  void begin(const std::string& phase) override { std::fprintf(stderr, "[%s]\n", phase.c_str()); }
  void end(const std::string& phase, double seconds) override {
    std::fprintf(stderr, "[%s] %.3f s\n", phase.c_str(), seconds);
  }
  void info(const std::string& message) override {
    std::fprintf(stderr, "  %s\n", message.c_str());
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s NX NY NZ [auto|cholmod|gamg] [tolerance] [threads]\n", argv[0]);
    return 1;
  }
  styk::testkit::CantileverSpec spec;
  spec.nx = std::atoi(argv[1]);
  spec.ny = std::atoi(argv[2]);
  spec.nz = std::atoi(argv[3]);
  styk::SolveOptions options;
  const std::string kind = argc > 4 ? argv[4] : "auto";
  if (kind == "cholmod") options.force = styk::LinearSolverKind::Cholmod;
  if (kind == "gamg" || kind == "compare") options.force = styk::LinearSolverKind::Iterative;
  if (argc > 5) options.iterative_tolerance = std::atof(argv[5]);
  if (argc > 6) options.threads = std::atoi(argv[6]);

  try {
    styk::ElementRegistry registry;
    styk::register_builtin_elements(registry);
    const auto start = std::chrono::steady_clock::now();
    const styk::testkit::Cantilever cantilever = styk::testkit::make_cantilever(spec, registry);
    const double build =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    StderrProgress progress;
    styk::AnalysisReport report;
    const auto solve_start = std::chrono::steady_clock::now();
    const styk::Results results =
        styk::run_static_analysis(cantilever.model, registry, options, &progress, &report);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - solve_start).count();
    const auto& U = results.increments.back().U;
    std::printf("mesh %dx%dx%d: %lld free dofs, %s\n", spec.nx, spec.ny, spec.nz, report.dofs,
                report.linear_solver.c_str());
    std::printf("model build %.2f s (not part of the analysis)\n", build);
    double solve_phases = 0.0;
    for (const styk::PhaseTiming& t : report.timings) {
      std::printf("  %-10s %8.3f s\n", t.phase.c_str(), t.seconds);
      if (t.phase == "order" || t.phase == "factorise" || t.phase == "solve")
        solve_phases += t.seconds;
    }
    std::printf("analysis wall %.3f s, non-solve share %.1f %%, CG iterations %d\n", wall,
                100.0 * (wall - solve_phases) / wall, report.iterations);
    if (cantilever.tip_centre_node >= 0)
      std::printf("tip uz = %.9e\n", U[cantilever.tip_centre_node][2]);
    if (kind == "compare") {
      styk::SolveOptions direct = options;
      direct.force = styk::LinearSolverKind::Cholmod;
      const styk::Results reference =
          styk::run_static_analysis(cantilever.model, registry, direct, nullptr, nullptr);
      const auto& R = reference.increments.back().U;
      double largest = 0.0, difference = 0.0;
      for (std::size_t n = 0; n < U.size(); ++n)
        for (int d = 0; d < 3; ++d) {
          largest = std::max(largest, std::abs(R[n][d]));
          difference = std::max(difference, std::abs(R[n][d] - U[n][d]));
        }
      std::printf("max |u_gamg - u_cholmod| / max |u| = %.3e\n", difference / largest);
      const auto& S = results.increments.back().S;
      const auto& SR = reference.increments.back().S;
      double largest_s = 0.0, difference_s = 0.0;
      for (std::size_t p = 0; p < S.size(); ++p)
        for (int k = 0; k < 6; ++k) {
          largest_s = std::max(largest_s, std::abs(SR[p][k]));
          difference_s = std::max(difference_s, std::abs(SR[p][k] - S[p][k]));
        }
      std::printf("max |S_gamg - S_cholmod| / max |S| = %.3e\n", difference_s / largest_s);
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
