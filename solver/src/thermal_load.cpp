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
    Eigen::VectorXd fe;
    std::vector<int> dofs;
    std::vector<double> f;  // this worker's share of the global vector
  };
  std::vector<Scratch> scratch(threads);
  parallel_for(model.element_count(), threads, 32, [&](int begin, int end, int worker) {
    Scratch& s = scratch[worker];
    if (s.f.empty()) s.f.assign(prepared.active_dofs(), 0.0);
    for (int e = begin; e < end; ++e) {
      if (!states.loaded(e)) continue;  // no change, no load (and no *EXPANSION needed)
      element_geometry(model, e, s.geometry);
      const ElementOptions options{model.sections[model.elements[e].section].selective_volumetric};
      prepared.formulation[e]->eigenstrain_load(s.geometry, states.law(e), prepared.rule_kind[e],
                                                s.fe, options, states.initial_stress(e));
      prepared.element_dofs(model, e, s.dofs);
      for (std::size_t i = 0; i < s.dofs.size(); ++i)
        s.f[s.dofs[i]] += s.fe(static_cast<Eigen::Index>(i));
    }
  });
  std::vector<double> f(prepared.active_dofs(), 0.0);
  for (const Scratch& s : scratch)
    for (std::size_t i = 0; i < s.f.size(); ++i) f[i] += s.f[i];
  return f;
}

}  // namespace styk::solver_detail
