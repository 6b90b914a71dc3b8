// One run of a study (build, solve, measure) and the series of runs: in this process, or each in
// a child process of its own so that its peak memory is its own (wait4's rusage).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/studies/results/run_record.hpp"
#include "styk/studies/study/problems.hpp"

namespace styk::studies {

struct RunSpec {
  std::string study;    // accuracy or stability (recorded)
  std::string problem;  // find_problem() name
  std::string family;
  int level = 0;
  int repeats = 3;  // timed solves; the record keeps the median
};

// Builds, solves `spec.repeats` times and measures in this process. A model the builder or the
// solver refuses becomes a record with `failure` set (never an exception); memory_mb stays NaN.
RunRecord run_in_process(const RunSpec& spec, const ElementRegistry& registry);

// The same run in a child process: `program` is the `styk` executable, run as
// `styk study run --study S --problem P --family F --level L --repeats N` (it prints the record's
// CSV row); memory_mb is the child's peak resident memory. A child that crashes or prints no
// record gives a record with `failure` set.
RunRecord run_isolated(const RunSpec& spec, const std::string& program);

// The warnings of an AnalysisReport by kind: "locking" (volumetric, or shear locking of beams and
// shells), "hourglass", "spurious modes" (zero-energy modes of beams and shells), "distortion"
// (or "other").
std::vector<std::string> warning_kinds(const std::vector<std::string>& warnings);

struct SeriesOptions {
  std::vector<std::string> families;  // empty: every available family of the problem's kind;
                                      // families of another kind are skipped
  long long max_dof = 500000;         // refinement stops before a level predicted to exceed it
  double max_seconds = 120;           // ... or predicted to solve slower than this
  int repeats = 3;                    // timed solves per run (1 for runs predicted over 30 s)
  int max_levels = 0;                 // > 0: at most this many levels per series
  std::string program;                // `styk` to isolate each run in a child; empty: in-process
  std::function<void(const std::string&)> progress;  // one line per run (may be empty)
};

// Runs `problem` for every family: a refinement series level by level until a limit is reached
// (a failed level ends its series), or a stability sweep over every value.
std::vector<RunRecord> run_problem(const ReferenceProblem& problem, const std::string& study,
                                   const ElementRegistry& registry, const SeriesOptions& options);

}  // namespace styk::studies
