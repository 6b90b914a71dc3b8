#include "styk/studies/verify/run_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include "styk/core/diagnostics.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::verify {
namespace {

const NodeSet& node_set(const BenchmarkCase& c, const Model& model) {
  const NodeSet* set = model.find_nset(c.measure.node_set);
  if (!set || set->nodes.empty())
    throw InputError({"styk verify " + c.name, 0},
                     "the builder '" + c.builder + "' made no node set " + c.measure.node_set);
  return *set;
}

// SPEC §3.1.8: sigma = E (1 - nu + 2 nu) e / ((1 + nu)(1 - 2 nu)) with every strain 1e-3 is 2000
// for E = 1e6, nu = 0.25; tau = G gamma = 400. The worst integration-point component, relative to
// its exact value, reported on the sigma scale.
double worst_patch_stress(const IncrementResult& result) {
  const double exact[6] = {2000, 2000, 2000, 400, 400, 400};
  double worst = 0.0;
  for (const Tensor6& s : result.S)
    for (int k = 0; k < 6; ++k) {
      const double deviation = (s[k] - exact[k]) / exact[k];
      if (std::abs(deviation) > std::abs(worst)) worst = deviation;
    }
  return 2000.0 * (1.0 + worst);
}

// Support::PlateSimplySupported (see its comment): keeps w = 0 on the builder's edge nodes that
// lie on the bottom face and removes the in-plane rigid-body motion at two bottom corners.
void simply_support_plate(const BenchmarkCase& c, Model& model) {
  const NodeSet* edges = model.find_nset("EDGES");
  if (!edges)
    throw InputError({"styk verify " + c.name, 0}, "the plate deck has no node set EDGES");
  double x_max = 0.0;
  for (const Vec3& x : model.coords) x_max = std::max(x_max, x[0]);
  const double tol = 1e-9 * x_max;
  model.boundaries.clear();
  for (int n : edges->nodes) {
    const Vec3& x = model.coords[n];
    if (std::abs(x[2]) > tol) continue;
    model.boundaries.push_back({n, 3, 0.0, {}});
    if (std::abs(x[1]) < tol && std::abs(x[0]) < tol) {
      model.boundaries.push_back({n, 1, 0.0, {}});
      model.boundaries.push_back({n, 2, 0.0, {}});
    }
    if (std::abs(x[1]) < tol && std::abs(x[0] - x_max) < tol)
      model.boundaries.push_back({n, 2, 0.0, {}});
  }
}

}  // namespace

Model build_case_model(const BenchmarkCase& c, const std::string& family,
                       const ElementRegistry& registry) {
  std::map<std::string, std::string> args = c.params;
  args["element"] = family;
  Model model = mesher::run_builder(c.builder, args, registry).model;
  if (c.support == Support::PlateSimplySupported) simply_support_plate(c, model);
  return model;
}

double measure_displacements(const BenchmarkCase& c, const Model& model,
                             const std::vector<Vec3>& U) {
  if (c.measure.kind == Measurement::Kind::WorstPatchStress)
    throw InputError({"styk verify " + c.name, 0},
                     "this case measures stresses, not displacements");
  const NodeSet& set = node_set(c, model);
  double sum = 0.0;
  for (int n : set.nodes) {
    if (c.measure.kind == Measurement::Kind::MeanRadial) {
      const Vec3& x = model.coords[n];
      const double r = std::hypot(x[0], x[1]);
      sum += (U[n][0] * x[0] + U[n][1] * x[1]) / r;
    } else {
      sum += U[n][c.measure.component];
    }
  }
  return c.measure.sign * sum / static_cast<double>(set.nodes.size());
}

double measure_case(const BenchmarkCase& c, const Model& model, const IncrementResult& result) {
  if (c.measure.kind == Measurement::Kind::WorstPatchStress) return worst_patch_stress(result);
  return measure_displacements(c, model, result.U);
}

double run_case(const BenchmarkCase& c, const std::string& family,
                const ElementRegistry& registry) {
  const Model model = build_case_model(c, family, registry);
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  return measure_case(c, model, results.increments.back());
}

std::vector<CaseOutcome> run_cases(const std::vector<BenchmarkCase>& cases,
                                   const ElementRegistry& registry,
                                   const std::function<void(const std::string&)>& progress) {
  std::vector<CaseOutcome> out;
  for (const BenchmarkCase& c : cases) {
    CaseOutcome outcome{c, {}};
    for (int f = 0; f < kFamilyCount; ++f) {
      const std::string family = kElementFamilies[f];
      if (progress) progress(c.name + " " + family);
      if (!registry.find(family)) {
        outcome.ours[f].failure = family + " is not registered (element plug-ins not loaded)";
        continue;
      }
      try {
        outcome.ours[f].value = run_case(c, family, registry);
      } catch (const std::exception& e) {
        outcome.ours[f].failure = e.what();
      }
    }
    out.push_back(std::move(outcome));
  }
  return out;
}

}  // namespace styk::verify
