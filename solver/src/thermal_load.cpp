#include "thermal_load.hpp"

#include "assembly.hpp"
#include "parallel.hpp"

namespace styk::solver_detail {

std::vector<std::vector<double>> step_temperature_changes(const Model& model) {
  const int nodes = model.node_count();
  const std::vector<double> initial = initial_node_temperatures(model);

  std::vector<double> current = initial;
  std::vector<std::vector<double>> out;
  out.reserve(model.steps.size());
  for (const Step& step : model.steps) {
    if (step.temperature_op_new) current = initial;
    for (const NodalTemperature& t : step.temperatures) {
      if (t.node < 0 || t.node >= nodes)
        throw InputError(t.where, "*TEMPERATURE on an undefined node");
      current[t.node] = t.value;
    }
    std::vector<double> dT(nodes);
    bool any = false;
    for (int n = 0; n < nodes; ++n) {
      dT[n] = current[n] - initial[n];
      any = any || dT[n] != 0.0;
    }
    out.push_back(any ? std::move(dT) : std::vector<double>{});
  }
  return out;
}

std::vector<std::vector<double>> step_temperatures(const Model& model) {
  const std::vector<double> initial = initial_node_temperatures(model);
  std::vector<std::vector<double>> out = step_temperature_changes(model);
  for (std::vector<double>& T : out)
    for (std::size_t n = 0; n < T.size(); ++n) T[n] += initial[n];
  return out;
}

std::vector<double> assemble_eigenstrain_load(const Model& model, const PreparedModel& prepared,
                                              const ElementStates& states, int threads) {
  threads = resolve_threads(threads);
  struct Scratch {
    ElementGeometry geometry;
  };
  std::vector<Scratch> scratch(threads);
  // Element loads computed in parallel and summed afterwards in element order, so that the load,
  // and the answer, is the same bit for bit whatever thread took which element.
  std::vector<Eigen::VectorXd> element_load(model.element_count());
  parallel_for(model.element_count(), threads, 32, [&](int begin, int end, int worker) {
    Scratch& s = scratch[worker];
    for (int e = begin; e < end; ++e) {
      if (!states.loaded(e)) continue;  // no change, no load (and no *EXPANSION needed)
      element_geometry(model, prepared, e, s.geometry);
      const ElementOptions options{model.sections[model.elements[e].section].selective_volumetric};
      prepared.formulation[e]->eigenstrain_load(s.geometry, states.law(e), prepared.rule_kind[e],
                                                element_load[e], options, states.initial_stress(e));
    }
  });
  std::vector<double> f(prepared.active_dofs(), 0.0);
  std::vector<int> dofs;
  for (int e = 0; e < model.element_count(); ++e) {
    if (element_load[e].size() == 0) continue;
    prepared.element_dofs(model, e, dofs);
    for (std::size_t i = 0; i < dofs.size(); ++i)
      f[dofs[i]] += element_load[e](static_cast<Eigen::Index>(i));
  }
  return f;
}

}  // namespace styk::solver_detail
