#include "body_loads.hpp"

#include <map>

#include "assembly.hpp"

namespace styk::solver_detail {

std::vector<double> assemble_body_loads(const Model& model, const PreparedModel& prepared,
                                        const ElementStates& states,
                                        const StepConditions& conditions) {
  if (conditions.body_loads.empty()) return {};
  // Every load of an element, summed into one acceleration field.
  std::map<int, BodyAcceleration> field;
  std::map<int, SourceLoc> first_line;
  for (const BodyLoad& load : conditions.body_loads) {
    field[load.element].add(load);
    first_line.emplace(load.element, load.where);
  }
  std::vector<double> f(prepared.active_dofs(), 0.0);
  ElementGeometry geometry;
  Eigen::VectorXd fe;
  std::vector<int> dofs;
  for (const auto& [e, acceleration] : field) {
    const Material& material = states.material_of(e);
    if (!material.density)
      throw InputError(first_line[e], "*DLOAD GRAV/CENTRIF on element " +
                                          std::to_string(model.elements[e].id) + ": its material " +
                                          material.name +
                                          " has no *DENSITY (a body force is per unit mass)");
    element_geometry(model, prepared, e, geometry);
    prepared.formulation[e]->body_load(geometry, *material.density, prepared.rule_kind[e],
                                       acceleration, fe);
    prepared.element_dofs(model, e, dofs);
    for (std::size_t i = 0; i < dofs.size(); ++i) f[dofs[i]] += fe(static_cast<Eigen::Index>(i));
  }
  return f;
}

}  // namespace styk::solver_detail
