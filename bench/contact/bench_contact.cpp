// Contact benchmark: for each model, the contact iterations per increment and the wall time of the
// whole analysis in units of one linear solve (assembly + ordering + factorisation + one
// forward/back substitution of the same stiffness). Prints one CSV line per model.
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "contact_spec_models.hpp"
#include "hex_model_builder.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/solver/analysis.hpp"

namespace {

using namespace styk;

// Collects the iteration counts of the converged increments from the progress lines.
class Recorder : public ProgressSink {
 public:
  void begin(const std::string&) override {}
  void end(const std::string& phase, double seconds) override {
    seconds_[phase] += seconds;
    ++calls_[phase];
  }
  void info(const std::string& line) override {
    const std::size_t at = line.find("converged in ");
    if (at != std::string::npos) iterations.push_back(std::stoi(line.substr(at + 13)));
  }
  double seconds(const std::string& phase) const {
    const auto it = seconds_.find(phase);
    return it == seconds_.end() ? 0.0 : it->second;
  }
  int calls(const std::string& phase) const {
    const auto it = calls_.find(phase);
    return it == calls_.end() ? 0 : it->second;
  }
  std::vector<int> iterations;

 private:
  std::map<std::string, double> seconds_;
  std::map<std::string, int> calls_;
};

void run(const char* name, const Model& model, const ElementRegistry& registry) {
  Recorder recorder;
  AnalysisReport report;
  const auto start = std::chrono::steady_clock::now();
  const Results results = run_static_analysis(model, registry, SolveOptions{}, &recorder, &report);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double solve =
      recorder.calls("solve") > 0 ? recorder.seconds("solve") / recorder.calls("solve") : 0.0;
  const double linear = recorder.seconds("assemble") / std::max(1, recorder.calls("assemble")) +
                        recorder.seconds("order") / std::max(1, recorder.calls("order")) +
                        recorder.seconds("factorise") / std::max(1, recorder.calls("factorise")) +
                        solve;
  int most = 0, total = 0;
  for (int n : recorder.iterations) {
    most = std::max(most, n);
    total += n;
  }
  std::size_t pairs = results.increments.empty() ? 0 : results.increments.back().contact.size();
  std::printf("%s,%d,%lld,%zu,%zu,%.2f,%d,%.3f,%.3f,%.3f,%.1f\n", name, model.element_count(),
              report.dofs, pairs, results.increments.size(),
              recorder.iterations.empty() ? 0.0 : double(total) / recorder.iterations.size(), most,
              wall, linear, recorder.seconds("contact compliance"), wall / linear);
  std::fflush(stdout);
}

}  // namespace

int main() {
  const auto full = styk::test::registry_with_plugins();
  std::printf(
      "model,elements,dofs,contact_nodes,increments,mean_iterations,max_iterations,"
      "wall_s,linear_solve_s,compliance_s,wall_over_linear\n");
  run("beams_mu0.2", test::two_cantilevers_model(test::coulomb(0.2)), full->registry);
  run("beams_mu10", test::two_cantilevers_model(test::coulomb(10.0)), full->registry);
  run("punch_mu0.04", test::punch_model(test::coulomb(0.04)), full->registry);
  run("punch_mu0.75", test::punch_model(test::coulomb(0.75)), full->registry);
  run("shrink_fit_2steps", test::shrink_fit_model(52.5), full->registry);
  // `styk mesh shrink-fit` model A at its default density (625 node pairs): heating with
  // mu = 0.2, then 52.5 and 72 MPa; the sleeve held axially by friction alone.
  run("shrink_fit_A_3steps", mesher::run_builder("shrink-fit", {}, full->registry).model,
      full->registry);
  return 0;
}
