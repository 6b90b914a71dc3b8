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
  for (const auto& [e, acceleration] : field) {
    const Material& material = states.material_of(e);
    if (!material.density)
      throw InputError(first_line[e], "*DLOAD GRAV/CENTRIF on element " +
                                          std::to_string(model.elements[e].id) + ": its material " +
                                          material.name +
                                          " has no *DENSITY (a body force is per unit mass)");
    element_geometry(model, e, geometry);
    prepared.formulation[e]->body_load(geometry, *material.density, RuleKind::Full, acceleration,
                                       fe);
    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < model.elements[e].node_count; ++k) {
      const int a = prepared.active_of_node[nodes[k]];
      for (int d = 0; d < 3; ++d) f[3 * a + d] += fe(3 * k + d);
    }
  }
  return f;
}

}  // namespace styk::solver_detail
