#include "penetration_steps.hpp"

#include <algorithm>

namespace styk::solver_detail {

std::vector<double> StepPenetration::at(double tau) const {
  std::vector<double> out(definitions.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = (1.0 - tau) * start[i] + tau * end[i];
  return out;
}

std::vector<StepPenetration> accumulate_penetrations(const Model& model) {
  std::vector<StepPenetration> out;
  StepPenetration previous;
  for (const Step& step : model.steps) {
    StepPenetration current;
    if (!step.penetration_op_new) current.definitions = previous.definitions;
    for (const PressurePenetration& pp : step.penetrations) {
      const auto same = std::find_if(current.definitions.begin(), current.definitions.end(),
                                     [&](const PressurePenetration* d) {
                                       return d->slave == pp.slave && d->master == pp.master;
                                     });
      if (same != current.definitions.end())
        *same = &pp;
      else
        current.definitions.push_back(&pp);
    }
    for (const PressurePenetration* d : current.definitions) {
      double start = 0.0;
      for (std::size_t i = 0; i < previous.definitions.size(); ++i)
        if (previous.definitions[i]->slave == d->slave &&
            previous.definitions[i]->master == d->master)
          start = previous.end[i];
      current.start.push_back(start);
      current.end.push_back(d->pressure);
    }
    out.push_back(current);
    previous = std::move(current);
  }
  return out;
}

std::vector<PenetrationResult> penetration_results(const Model& model,
                                                   const contact::PenetrationLayout& layout,
                                                   const contact::ContactState& state,
                                                   const std::vector<double>& pressures) {
  std::vector<PenetrationResult> out;
  for (std::size_t z = 0; z < layout.zones.size(); ++z) {
    const contact::PenetrationZone& zone = layout.zones[z];
    PenetrationResult r;
    const auto pair = std::find_if(
        model.contact_pairs.begin(), model.contact_pairs.end(), [&](const ContactPair& p) {
          return p.slave == zone.definition->slave && p.master == zone.definition->master;
        });
    r.pair = static_cast<int>(pair - model.contact_pairs.begin());
    r.pressure = pressures[z];
    r.penetrated = contact::penetrated_count(zone, state);
    r.nodes = static_cast<int>(zone.constraints.size());
    r.leaked = contact::leaks(zone, state);
    out.push_back(r);
  }
  return out;
}

}  // namespace styk::solver_detail
