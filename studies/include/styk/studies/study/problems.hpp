// The reference problems of the studies, as data: which mesher builder makes each level of a
// refinement series (or each point of a stability sweep), the exact solution it is measured
// against, the boundary conditions taken from that solution, and the named points
// (docs/accuracy.md lists them with their sources).
#pragma once

#include <array>
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
#include "styk/studies/study/families.hpp"

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
  // Beams and plates: the model is a CalculiX deck (text for the family), read by the .inp
  // reader instead of a builder's; and its errors come from `measure` (named points against a
  // closed form or series) instead of a 3D exact field.
  std::function<std::string(const ElementFamily& family)> deck;
  std::function<ErrorArray(const Model&, const IncrementResult&, const ElementRegistry&)> measure;
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
  ElementKind kind = ElementKind::Solid;  // the families it runs
  // The error of the charts and of the "fastest to reach" tables: the energy norm for solids,
  // the named point's stress (moment) for beams and plates, which have no 3D field.
  Measure headline = Measure::Energy;
  // Beams and plates: the theoretical orders (against h) of the named point's displacement and
  // stress (moment) errors of a family, which the page compares with the fitted ones; solids are
  // compared on their L2 and energy norms (p + 1, p) instead.
  std::function<std::array<int, 2>(const ElementFamily&)> point_orders;

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
// imposed (or the setup's deck for the family, read by the .inp reader). Throws InputError from
// the builder or the reader.
Model build_problem_model(const ProblemSetup& setup, const std::string& family,
                          const ElementRegistry& registry);

}  // namespace styk::studies
