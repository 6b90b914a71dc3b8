#include "styk/studies/study/run.hpp"

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <sstream>

#include "styk/core/diagnostics.hpp"
#include "styk/solver/analysis.hpp"
#include "styk/studies/study/families.hpp"

extern char** environ;

namespace styk::studies {
namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? kNaN : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

RunRecord blank_record(const RunSpec& spec) {
  RunRecord r;
  r.study = spec.study;
  r.problem = spec.problem;
  r.family = spec.family;
  r.level = spec.level;
  return r;
}

// Builds and solves; fills the record or throws.
void build_solve_measure(const RunSpec& spec, const ReferenceProblem& problem,
                         const ElementRegistry& registry, RunRecord& r) {
  const ProblemSetup setup = problem.setup(spec.level);
  r.h = setup.h;
  if (!problem.parameter.empty()) {
    r.parameter = problem.parameter;
    r.value = problem.values.at(spec.level);
  }
  const Model model = build_problem_model(setup, spec.family, registry);
  r.elements = model.element_count();
  std::vector<double> seconds;
  Results results;
  AnalysisReport report;
  for (int k = 0; k < std::max(1, spec.repeats); ++k) {
    report = AnalysisReport{};
    const auto start = std::chrono::steady_clock::now();
    results = run_static_analysis(model, registry, SolveOptions{}, nullptr, &report);
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  r.time_s = median(seconds);
  r.runs = static_cast<int>(seconds.size());
  r.dof = report.dofs;
  r.warnings = warning_kinds(report.warnings);
  if (setup.quantities) r.quantities = setup.quantities(model, results);
  if (setup.measure) {
    const ErrorArray errors = setup.measure(model, results.increments.back(), registry);
    for (int m = 0; m < kMeasureCount; ++m) r.error[m] = errors[m];
    return;
  }
  if (!setup.exact) return;
  const ErrorArray errors =
      measure_errors(model, results.increments.back(), registry, *setup.exact, setup.probes);
  for (int m = 0; m < kMeasureCount; ++m) r.error[m] = errors[m];
}

std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

}  // namespace

std::vector<std::string> warning_kinds(const std::vector<std::string>& warnings) {
  std::vector<std::string> kinds;
  for (const std::string& w : warnings) {
    const auto has = [&w](const char* text) { return w.find(text) != std::string::npos; };
    const std::string kind =
        has("lock volumetrically") || has("shear locking") || has("locks in shear") ? "locking"
        : has("hourglass")                                                          ? "hourglass"
        : has("zero-energy modes")     ? "spurious modes"
        : has("thick for a Kirchhoff") ? "no shear deflection"
        : has("distorted")             ? "distortion"
                                       : "other";
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) kinds.push_back(kind);
  }
  return kinds;
}

RunRecord run_in_process(const RunSpec& spec, const ElementRegistry& registry) {
  RunRecord r = blank_record(spec);
  const ReferenceProblem* problem = find_problem(spec.problem);
  if (!problem) {
    r.failure = "unknown problem '" + spec.problem + "'";
    return r;
  }
  if (spec.level < 0 || spec.level >= problem->level_count()) {
    r.failure = "level " + std::to_string(spec.level) + " is outside 0.." +
                std::to_string(problem->level_count() - 1);
    return r;
  }
  try {
    build_solve_measure(spec, *problem, registry, r);
  } catch (const std::exception& e) {
    r.failure = one_line(e.what());
  }
  return r;
}

RunRecord run_isolated(const RunSpec& spec, const std::string& program) {
  RunRecord failed = blank_record(spec);
  int out[2];
  if (pipe(out) != 0) {
    failed.failure = std::string("pipe: ") + std::strerror(errno);
    return failed;
  }
  std::vector<std::string> args = {program,
                                   "study",
                                   "run",
                                   "--study",
                                   spec.study,
                                   "--problem",
                                   spec.problem,
                                   "--family",
                                   spec.family,
                                   "--level",
                                   std::to_string(spec.level),
                                   "--repeats",
                                   std::to_string(spec.repeats)};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  if (spawned != 0) {
    close(out[0]);
    failed.failure = "cannot run " + program + ": " + std::strerror(spawned);
    return failed;
  }
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = read(out[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
  close(out[0]);
  int status = 0;
  struct rusage usage {};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    failed.failure = WIFSIGNALED(status)
                         ? "the run was killed by signal " + std::to_string(WTERMSIG(status))
                         : "the run exited with status " + std::to_string(WEXITSTATUS(status));
    return failed;
  }
  std::istringstream lines(text);
  std::string line, last;
  while (std::getline(lines, line))
    if (!line.empty()) last = line;
  try {
    RunRecord r = parse_csv_row(last, "styk study run", 1);
    r.memory_mb = usage.ru_maxrss / 1024.0;  // Linux reports kilobytes
    return r;
  } catch (const std::exception& e) {
    failed.failure = std::string("the run printed no record: ") + e.what();
    return failed;
  }
}

std::vector<RunRecord> run_problem(const ReferenceProblem& problem, const std::string& study,
                                   const ElementRegistry& registry, const SeriesOptions& options) {
  std::vector<std::string> families;
  if (options.families.empty()) {
    for (const ElementFamily& f : available_families(registry, nullptr))
      if (f.kind == problem.kind) families.push_back(f.name);
  } else {
    for (const std::string& name : options.families) {
      const ElementFamily* f = find_family(name);
      if (!f || f->kind == problem.kind) families.push_back(name);  // unknown: its run says why
    }
  }
  const bool sweep = !problem.parameter.empty();
  std::vector<RunRecord> out;
  for (const std::string& family : families) {
    if (std::find(problem.skip_families.begin(), problem.skip_families.end(), family) !=
        problem.skip_families.end())
      continue;
    std::vector<std::size_t> done;  // indices into `out` of this series' finished levels
    int levels = problem.level_count();
    if (!sweep && options.max_levels > 0) levels = std::min(levels, options.max_levels);
    for (int level = 0; level < levels; ++level) {
      RunSpec spec{study, problem.name, family, level, options.repeats};
      if (!sweep && done.size() >= 2) {
        // Predict the next level from the growth of the last one.
        const RunRecord& a = out[done[done.size() - 2]];
        const RunRecord& b = out[done.back()];
        const double dof_growth = static_cast<double>(b.dof) / std::max<long long>(1, a.dof);
        const double time_growth = std::max(1.0, b.time_s / std::max(1e-6, a.time_s));
        if (b.dof * dof_growth > options.max_dof) break;
        const double predicted = b.time_s * std::max(time_growth, dof_growth);
        if (predicted > options.max_seconds) break;
        if (predicted > 30) spec.repeats = 1;
      }
      if (options.progress)
        options.progress(problem.name + " " + family + " level " + std::to_string(level));
      out.push_back(options.program.empty() ? run_in_process(spec, registry)
                                            : run_isolated(spec, options.program));
      if (options.progress && !out.back().ok()) options.progress("  failed: " + out.back().failure);
      if (!sweep && !out.back().ok()) break;
      done.push_back(out.size() - 1);
    }
  }
  return out;
}

}  // namespace styk::studies
