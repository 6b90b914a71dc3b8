#include "element_states.hpp"

namespace styk::solver_detail {
namespace {

bool temperature_dependent_stiffness(const Material& m) { return m.elastic_table.size() > 1; }

}  // namespace

std::vector<double> initial_node_temperatures(const Model& model) {
  std::vector<double> initial(model.node_count(), 0.0);
  for (const NodalTemperature& t : model.initial_temperatures)
    if (t.node >= 0 && t.node < model.node_count()) initial[t.node] = t.value;
  return initial;
}

ElementStates::ElementStates(const Model& model, const PreparedModel& prepared, std::size_t step,
                             const std::vector<double>* temperature)
    : model_(model),
      prepared_(prepared),
      temperature_(temperature),
      initial_(initial_node_temperatures(model)),
      material_(prepared.material) {
  axes_.assign(model.sections.size(), nullptr);
  for (std::size_t s = 0; s < model.sections.size(); ++s) {
    const std::string& name = model.sections[s].orientation;
    if (name.empty()) continue;
    const auto it = model.orientations.find(name);
    if (it == model.orientations.end())
      throw InputError(model.sections[s].where,
                       "*SOLID SECTION: ORIENTATION=" + name + " is not defined");
    axes_[s] = &it->second.axes;
  }
  // *CHANGE SOLID SECTION of the steps up to this one, in order: the elements of the section
  // of the named set take the new material.
  for (std::size_t k = 0; k <= step && k < model.steps.size(); ++k)
    for (const SectionChange& change : model.steps[k].section_changes) {
      const ElementSet* set = model.find_elset(change.elset);
      if (!set || change.material_index < 0)
        throw InputError(change.where, "*CHANGE SOLID SECTION: element set " + change.elset +
                                           " or material " + change.material + " is undefined");
      const Material& material = model.materials[change.material_index];
      check_elasticity(material);
      for (int e : set->elements) material_[e] = &material;
    }
  for (const InitialStress& s : model.initial_stresses) {
    const int points = prepared.ip_offset[s.element + 1] - prepared.ip_offset[s.element];
    if (s.point < 1 || s.point > points)
      throw InputError(s.where, "*INITIAL CONDITIONS, TYPE=STRESS: element " +
                                    std::to_string(model.elements[s.element].id) + " (" +
                                    model.elements[s.element].type + ") has " +
                                    std::to_string(points) + " integration points, not " +
                                    std::to_string(s.point));
    Eigen::MatrixXd& rows = initial_stress_[s.element];
    if (rows.size() == 0) rows.setZero(points, 6);
    for (int c = 0; c < 6; ++c) rows(s.point - 1, c) = s.stress[c];
  }
}

const Material& ElementStates::material_of(int e) const { return *material_[e]; }

Eigen::VectorXd ElementStates::nodal(const std::vector<double>& values, int e) const {
  const int n = model_.elements[e].node_count;
  const int* nodes = model_.element_nodes(e);
  Eigen::VectorXd out(n);
  for (int k = 0; k < n; ++k) out(k) = values[nodes[k]];
  return out;
}

ElementMaterial ElementStates::stiffness_law(int e) const {
  const Material& m = *material_[e];
  const LocalAxes* axes = axes_[model_.elements[e].section];
  if (!temperature_dependent_stiffness(m)) return ElementMaterial(m, axes, {}, {});
  const Eigen::VectorXd T0 = nodal(initial_, e);
  return ElementMaterial(m, axes, temperature_ ? nodal(*temperature_, e) : T0, T0);
}

ElementMaterial ElementStates::law(int e) const {
  const Material& m = *material_[e];
  const LocalAxes* axes = axes_[model_.elements[e].section];
  // At the initial temperatures there is no thermal strain: only a temperature-dependent law
  // needs them (the common case allocates nothing).
  if (!temperature_ && !temperature_dependent_stiffness(m)) return ElementMaterial(m, axes, {}, {});
  const Eigen::VectorXd T0 = nodal(initial_, e);
  return ElementMaterial(m, axes, temperature_ ? nodal(*temperature_, e) : T0, T0);
}

const Eigen::MatrixXd* ElementStates::initial_stress(int e) const {
  const auto it = initial_stress_.find(e);
  return it == initial_stress_.end() ? nullptr : &it->second;
}

bool ElementStates::loaded(int e) const {
  if (initial_stress_.count(e) != 0) return true;
  if (!temperature_) return false;
  const int n = model_.elements[e].node_count;
  const int* nodes = model_.element_nodes(e);
  for (int k = 0; k < n; ++k)
    if ((*temperature_)[nodes[k]] != initial_[nodes[k]]) return true;
  return false;
}

bool ElementStates::stiffness_differs(const ElementStates& other) const {
  bool tabulated = false;
  for (int e = 0; e < model_.element_count(); ++e) {
    if (material_[e] != other.material_[e]) return true;
    tabulated = tabulated || temperature_dependent_stiffness(*material_[e]);
  }
  if (!tabulated) return false;
  const std::vector<double>& mine = temperature_ ? *temperature_ : initial_;
  const std::vector<double>& theirs = other.temperature_ ? *other.temperature_ : other.initial_;
  return mine != theirs;
}

}  // namespace styk::solver_detail
