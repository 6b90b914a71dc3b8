// The reference problems of the studies, as data: which mesher builder makes each level of a
// refinement series (or each point of a stability sweep), the exact solution it is measured
// against, the boundary conditions taken from that solution, and the named points
// (docs/accuracy.md lists them with their sources).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/studies/study/error_measures.hpp"
#include "styk/studies/study/exact_solution.hpp"

namespace styk::studies {

// One model of a series: the builder and its parameters (--element is added per family), the
// element size, the exact solution, the named points, and what replaces the builder's supports
// and loads by the exact ones (empty: the builder's deck is already the exact problem).
struct ProblemSetup {
  std::string builder;
  std::map<std::string, std::string> args;
  double h = 0.0;
  std::shared_ptr<const ExactSolution> exact;  // null: no exact solution, no errors measured
  ProblemProbes probes;
  std::function<void(const mesher::BuildResult&, Model&, const ElementRegistry&)> impose;
  // Absolute results recorded by name (RunRecord::quantities); may be empty.
  std::function<std::map<std::string, double>(const Model&, const Results&)> quantities;
};

struct ReferenceProblem {
  std::string name;     // e.g. "lame"; `styk study run --problem NAME`
  std::string title;    // e.g. "Lamé thick cylinder, nu = 0.3"
  std::string source;   // SPEC section and the published solution
  std::string details;  // mesh series, supports, named points: for the docs
  // A stability sweep varies `parameter` over `values` on one mesh (level = index into values);
  // a refinement series has no parameter and levels 0 .. levels - 1.
  std::string parameter;
  std::vector<double> values;
  bool log_parameter = false;  // the sweep's values span decades
  int levels = 0;
  std::vector<std::string> skip_families;  // families the problem cannot run, with the reason in
                                           // `details`
  // Why a family's fitted orders may miss the theory on this problem (family -> reason), for the
  // page's list of deviations; a deviation without an entry is listed as unexplained.
  std::map<std::string, std::string> deviations;
  std::function<ProblemSetup(int level)> setup;

  int level_count() const { return parameter.empty() ? levels : static_cast<int>(values.size()); }
};

// The refinement series of `styk study accuracy`, in report order.
const std::vector<ReferenceProblem>& accuracy_problems();
// The sweeps of `styk study stability`, in report order.
const std::vector<ReferenceProblem>& stability_sweeps();
// The models of `styk study model-size` (the SPEC §4.2 shrink fit as full, quarter and sector
// model), in report order; the families it compares by default.
const std::vector<ReferenceProblem>& model_size_problems();
const std::vector<std::string>& model_size_families();
// Any kind, by name; nullptr if none.
const ReferenceProblem* find_problem(const std::string& name);

// The model of one run: the setup's builder with --element `family`, the exact conditions
// imposed. Throws InputError from the builder.
Model build_problem_model(const ProblemSetup& setup, const std::string& family,
                          const ElementRegistry& registry);

}  // namespace styk::studies
