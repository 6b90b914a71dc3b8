#include "step_conditions.hpp"

#include <map>
#include <utility>

namespace styk::solver_detail {
namespace {

int checked_dof(const Model& model, const PreparedModel& prepared, int node, int dof,
                const SourceLoc& where, const char* what) {
  if (node < 0 || node >= model.node_count())
    throw InputError(where, std::string(what) + " on an undefined node");
  if (dof < 1 || dof > 3)
    throw InputError(where, std::string(what) + " on degree of freedom " + std::to_string(dof) +
                                " of node " + std::to_string(model.node_ids[node]) +
                                ": solid elements have only the displacements 1, 2, 3");
  const int active = prepared.active_of_node[node];
  if (active < 0)
    throw InputError(where, std::string(what) + " on node " +
                                std::to_string(model.node_ids[node]) +
                                ", which belongs to no element (it has no stiffness)");
  return 3 * active + dof - 1;
}

std::vector<DofValue> to_vector(const std::map<int, double>& values) {
  std::vector<DofValue> out;
  out.reserve(values.size());
  for (const auto& [dof, value] : values) out.push_back({dof, value});
  return out;
}

}  // namespace

std::vector<StepConditions> accumulate_step_conditions(const Model& model,
                                                       const PreparedModel& prepared) {
  std::map<int, double> model_level;
  for (const Boundary& b : model.boundaries)
    model_level[checked_dof(model, prepared, b.node, b.dof, b.where, "boundary condition")] =
        b.value;

  std::map<int, double> prescribed = model_level;
  std::map<int, double> nodal_loads;
  std::map<std::pair<int, int>, DistributedLoad> pressures;
  std::vector<StepConditions> out;
  out.reserve(model.steps.size());
  for (const Step& step : model.steps) {
    if (step.boundary_op_new) prescribed = model_level;
    if (step.cload_op_new) nodal_loads.clear();
    if (step.dload_op_new) pressures.clear();
    for (const Boundary& b : step.boundaries)
      prescribed[checked_dof(model, prepared, b.node, b.dof, b.where, "boundary condition")] =
          b.value;
    for (const ConcentratedLoad& c : step.cloads)
      nodal_loads[checked_dof(model, prepared, c.node, c.dof, c.where, "concentrated load")] =
          c.value;
    for (const DistributedLoad& d : step.dloads) {
      if (d.element < 0 || d.element >= model.element_count())
        throw InputError(d.where, "distributed load on an undefined element");
      const int faces = static_cast<int>(prepared.formulation[d.element]->faces().size());
      if (d.face < 1 || d.face > faces)
        throw InputError(d.where, "element " + std::to_string(model.elements[d.element].id) +
                                      " (" + model.elements[d.element].type + ") has faces 1.." +
                                      std::to_string(faces) + ", not " + std::to_string(d.face));
      pressures[{d.element, d.face}] = d;
    }
    StepConditions conditions;
    conditions.prescribed = to_vector(prescribed);
    conditions.nodal_loads = to_vector(nodal_loads);
    for (const auto& entry : pressures) conditions.pressures.push_back(entry.second);
    out.push_back(std::move(conditions));
  }
  return out;
}

std::vector<int> prescribed_dofs(const StepConditions& conditions) {
  std::vector<int> dofs;
  dofs.reserve(conditions.prescribed.size());
  for (const DofValue& p : conditions.prescribed) dofs.push_back(p.dof);
  return dofs;
}

}  // namespace styk::solver_detail
