// The models of `styk study model-size` (docs/model-size.md): the SPEC §4.2 shrink fit heated into
// its sleeve, as the full joint (model B), a quarter (model A) and a thin sector (model C, two
// elements of 7.5 deg around): the heating is axisymmetric, so symmetry planes carry the rest of
// the joint and every model should give the same answer.
#include <cmath>
#include <limits>

#include "problem_support.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/studies/study/problems.hpp"

namespace styk::studies {
namespace {

int node_nearest(const Model& model, const Vec3& at) {
  int best = -1;
  double best_d = INFINITY;
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    const double d = std::hypot(x[0] - at[0], x[1] - at[1], x[2] - at[2]);
    if (d < best_d) best_d = d, best = n;
  }
  if (best < 0 || best_d > 1e-6)
    throw InputError({model.source, 0}, "the shrink-fit model has no node at (" +
                                            detail::text(at[0]) + ", " + detail::text(at[1]) +
                                            ", " + detail::text(at[2]) + ")");
  return best;
}

// Tab 4.1's shaft-end results and the contact pressure after the heating step.
std::map<std::string, double> fit_results(const Model& model, const Results& results) {
  const IncrementResult& r = results.increments.back();
  std::map<std::string, double> q;
  q["elongation"] = r.U.at(node_nearest(model, {0, 0, 60}))[2];
  q["diametral_growth"] = 2 * r.U.at(node_nearest(model, {10, 0, 60}))[0];
  double sum = 0, area = 0, max = 0;
  int mid_slave = -1;
  double mid_d = INFINITY;
  for (const ContactNodeResult& c : r.contact) {
    const double a = c.area > 0 ? c.area : 1.0;
    sum += a * c.pressure;
    area += a;
    max = std::max(max, c.pressure);
    const Vec3& x = model.coords[c.node];
    const double d = std::hypot(x[0] - 10, x[1], x[2] - 30);
    if (d < mid_d) mid_d = d, mid_slave = static_cast<int>(&c - r.contact.data());
  }
  if (mid_slave < 0)
    throw InputError({model.source, 0}, "the shrink-fit model reported no contact nodes");
  q["pressure_mid"] = r.contact[mid_slave].pressure;
  q["pressure_mean"] = sum / area;
  q["pressure_max"] = max;
  q["slave_nodes"] = static_cast<double>(r.contact.size());
  return q;
}

ReferenceProblem fit_model(const std::string& name, const std::string& model,
                           const std::string& title) {
  ReferenceProblem p;
  p.name = name;
  p.title = title;
  p.source = "SPEC §4.2 shrink fit, step 1 (heating)";
  p.details = "Shaft 60 x D20 heated by 100 (alpha 2e-5) into the sleeve 20 x D20/D30, mu = 0.2";
  p.levels = 1;
  p.setup = [model](int) {
    ProblemSetup s;
    s.builder = "shrink-fit";
    s.args = {{"model", model}, {"load-case", "fit"}};
    s.h = 20.0 / 12;  // the default mesh's axial element length along the sleeve
    s.quantities = fit_results;
    return s;
  };
  return p;
}

}  // namespace

const std::vector<ReferenceProblem>& model_size_problems() {
  static const std::vector<ReferenceProblem> problems = {
      fit_model("shrink-fit-full", "B", "Full joint (model B)"),
      fit_model("shrink-fit-quarter", "A", "Quarter, two symmetry planes (model A)"),
      fit_model("shrink-fit-sector", "C",
                "Sector of 15 deg, two symmetry planes (model C, --sector-around 2)")};
  return problems;
}

const std::vector<std::string>& model_size_families() {
  static const std::vector<std::string> families = {"C3D21", "C3D27", "C3D20"};
  return families;
}

}  // namespace styk::studies
