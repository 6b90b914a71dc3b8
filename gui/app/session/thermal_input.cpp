#include "session/thermal_input.hpp"

#include <algorithm>

#include "session/input_checks.hpp"

namespace styk::gui {
namespace {

// `list` with every node of `nodes` set to `value` (existing entries replaced, others kept).
std::vector<NodalTemperature> with_values(std::vector<NodalTemperature> list,
                                          const std::vector<int>& nodes, double value) {
  list.erase(std::remove_if(list.begin(), list.end(),
                            [&](const NodalTemperature& t) {
                              return std::binary_search(nodes.begin(), nodes.end(), t.node);
                            }),
             list.end());
  for (int n : nodes) list.push_back({n, value, {}});
  return list;
}

std::vector<NodalTemperature>& temperatures_of(Model& m, int step) {
  return step < 0 ? m.initial_temperatures : m.steps.at(step).temperatures;
}

}  // namespace

std::unique_ptr<Command> temperature_command(const Model& model, const TemperatureInput& in) {
  const NodeSet& set = existing_nset(model, in.nset);
  check_step(model, in.step, true);
  if (in.step >= 0 && model.steps[in.step].kind != StepKind::Static)
    refuse("step " + model.steps[in.step].name + " is a " +
           step_kind_name(model.steps[in.step].kind) +
           " step: *TEMPERATURE is a thermal load of a static step (in a heat step prescribe the "
           "temperature as a boundary condition, dof 11)");
  check_finite(in.value, "temperature");
  const std::vector<NodalTemperature>& current =
      in.step < 0 ? model.initial_temperatures : model.steps[in.step].temperatures;
  std::vector<NodalTemperature> after = with_values(current, set.nodes, in.value);
  std::string text = in.step < 0
                         ? "Initial temperature of " + set.name
                         : "Temperature of " + set.name + " in " + model.steps[in.step].name;
  return make_model_edit(
      std::move(text), [after, step = in.step](Model& m) { temperatures_of(m, step) = after; },
      [before = current, step = in.step](Model& m) { temperatures_of(m, step) = before; });
}

}  // namespace styk::gui
