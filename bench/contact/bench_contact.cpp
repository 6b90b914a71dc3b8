// Contact benchmark: for each model, the contact iterations per increment and the wall time of the
// whole analysis in units of one linear solve (assembly + ordering + factorisation + one
// forward/back substitution of the same stiffness). Prints one CSV line per model.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "compliance_ab.hpp"
#include "contact_spec_models.hpp"
#include "hex_model_builder.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/solver/analysis.hpp"

namespace {

using namespace styk;

// Collects the iteration counts of the converged increments from the progress lines.
class Recorder : public ProgressSink {
 public:
  explicit Recorder(bool echo) : echo_(echo) {}
  void begin(const std::string&) override {}
  void end(const std::string& phase, double seconds) override {
    seconds_[phase] += seconds;
    ++calls_[phase];
  }
  void info(const std::string& line) override {
    if (echo_) std::fprintf(stderr, "%s\n", line.c_str());
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
  bool echo_ = false;
};

// Command line: `--log` echoes the solver's progress lines (every contact iteration) to stderr;
// `--compliance` times the two compliance paths instead (compliance_ab.hpp); any other argument
// is a model name to run (default: all).
struct Options {
  bool log = false;
  bool compliance = false;
  std::vector<std::string> only;
  bool wants(const std::string& name) const {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
  }
};

// The friction coefficient a model name ends with ("beams_mu5.5" -> 5.5); exits on a malformed
// one rather than running another model than the one asked for.
double friction_of(const std::string& name, const std::string& prefix) {
  const std::string digits = name.substr(prefix.size());
  char* end = nullptr;
  const double mu = std::strtod(digits.c_str(), &end);
  if (digits.empty() || *end != '\0' || !(mu >= 0.0)) {
    std::fprintf(stderr, "%s: not a friction coefficient after %s\n", name.c_str(), prefix.c_str());
    std::exit(2);
  }
  return mu;
}

// The name of a friction coefficient as the model names spell it: 0.2, 10, 5.5.
std::string format_mu(double mu) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", mu);
  return text;
}

void run(const char* name, const Model& model, const ElementRegistry& registry,
         const Options& options) {
  Recorder recorder(options.log);
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
  // Where the time goes: the compliance, the active-set iterations (dense assembly and LU of the
  // closed rows per iteration) and the recovery of the converged increments.
  std::printf("%s,%d,%lld,%zu,%zu,%.2f,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.1f\n", name,
              model.element_count(), report.dofs, pairs, results.increments.size(),
              recorder.iterations.empty() ? 0.0 : double(total) / recorder.iterations.size(), most,
              wall, linear, recorder.seconds("contact compliance"),
              recorder.seconds("contact iteration"), recorder.seconds("recover"), wall / linear);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--log")
      options.log = true;
    else if (std::string(argv[i]) == "--compliance")
      options.compliance = true;
    else
      options.only.emplace_back(argv[i]);
  }
  const auto full = styk::test::registry_with_plugins();
  if (options.compliance)
    std::printf(
        "model,dofs,columns,dense_blocks_s,restricted_1_thread_s,restricted_2_threads_s,"
        "speedup_1,speedup_2,max_rel_difference\n");
  else
    std::printf(
        "model,elements,dofs,contact_nodes,increments,mean_iterations,max_iterations,"
        "wall_s,linear_solve_s,compliance_s,iterations_s,recover_s,wall_over_linear\n");
  const auto maybe = [&](const char* name, auto&& build) {
    if (!options.wants(name)) return;
    if (options.compliance)
      bench::compliance_ab(name, build(), full->registry);
    else
      run(name, build(), full->registry, options);
  };
  // The beams and the punch at the default friction coefficients, and at any other asked for by
  // name (beams_mu5.5, punch_mu0.3): the iteration count of a slip front depends on mu.
  const auto frictional = [&](const char* model, std::vector<double> defaults, auto&& build) {
    const std::string prefix = std::string(model) + "_mu";
    for (const std::string& name : options.only)
      if (name.rfind(prefix, 0) == 0) defaults.push_back(friction_of(name, prefix));
    std::sort(defaults.begin(), defaults.end());
    defaults.erase(std::unique(defaults.begin(), defaults.end()), defaults.end());
    for (double mu : defaults) maybe((prefix + format_mu(mu)).c_str(), [&] { return build(mu); });
  };
  frictional("beams", {0.2, 10.0, 100.0},
             [](double mu) { return test::two_cantilevers_model(test::coulomb(mu)); });
  frictional("punch", {0.04, 0.75}, [](double mu) { return test::punch_model(test::coulomb(mu)); });
  maybe("shrink_fit_2steps", [] { return test::shrink_fit_model(52.5); });
  // `styk mesh shrink-fit` model A at its default density (625 node pairs): heating with
  // mu = 0.2, then 52.5 and 72 MPa; the sleeve held axially by friction alone.
  maybe("shrink_fit_A_3steps",
        [&] { return mesher::run_builder("shrink-fit", {}, full->registry).model; });
  // Model B as its 90-degree sector under a prescribed rotation to 1.5 degrees (full slip), at
  // the density of tests/verification/spec_4_2_model_b_torque_test.cpp and at the builder's
  // default density (600 constraints, 1800 frictional rows).
  maybe("shrink_fit_B_sector_coarse", [&] {
    const std::map<std::string, std::string> coarse{
        {"model", "B"},        {"sector", "yes"},    {"around", "4"},
        {"fit-rows", "4"},     {"end-rows", "3"},    {"shaft-rings", "2"},
        {"sleeve-rings", "2"}, {"element", "C3D21"}, {"load-case", "rotation"}};
    return mesher::run_builder("shrink-fit", coarse, full->registry).model;
  });
  maybe("shrink_fit_B_sector", [&] {
    const std::map<std::string, std::string> sector{
        {"model", "B"}, {"sector", "yes"}, {"load-case", "rotation"}};
    return mesher::run_builder("shrink-fit", sector, full->registry).model;
  });
  return 0;
}
