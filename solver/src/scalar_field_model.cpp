#include "scalar_field_model.hpp"

#include <numeric>

#include "scalar_element.hpp"
#include "styk/core/step_kind.hpp"

namespace styk::solver_detail {
namespace {

std::string element_label(const Element& element) {
  return "element " + std::to_string(element.id) + " (" + element.type + ")";
}

// Everything of the deck a scalar-field analysis would otherwise ignore is refused by name.
void refuse_mechanical_features(const Model& model, const char* procedure) {
  const std::string in = std::string(" in a deck of ") + procedure + " steps";
  if (!model.contact_pairs.empty())
    throw InputError(model.contact_pairs.front().where,
                     "*CONTACT PAIR" + in + ": Styk's scalar fields have no contact conductance");
  if (!model.equations.empty())
    throw InputError(model.equations.front().where,
                     "*EQUATION" + in + ": equations act on displacement dofs only");
  if (!model.cyclic_symmetries.empty())
    throw InputError(
        model.cyclic_symmetries.front().where,
        "*TIE, CYCLIC SYMMETRY" + in + ": cyclic symmetry acts on displacement dofs only");
  if (!model.transforms.empty())
    throw InputError(model.transforms.front().where,
                     "*TRANSFORM" + in + ": local systems act on displacement dofs only");
  if (!model.initial_temperatures.empty())
    throw InputError(model.initial_temperatures.front().where,
                     "*INITIAL CONDITIONS" + in +
                         ": a steady state does not depend on initial values; prescribe "
                         "temperatures with *BOUNDARY, dof 11");
}

Eigen::Vector3d checked_conductivity(const Model& model, const Element& element, StepKind kind) {
  const Section& section = model.sections[element.section];
  if (section.material_index < 0 ||
      section.material_index >= static_cast<int>(model.materials.size()))
    throw InputError(section.where, "the section of element set " + section.elset +
                                        " refers to an undefined material " + section.material);
  const Material& material = model.materials[section.material_index];
  const bool heat = kind == StepKind::HeatTransfer;
  const auto& k = heat ? material.conductivity : material.electrical_conductivity;
  if (!k)
    throw InputError(material.where,
                     "material " + material.name + " has no " +
                         (heat ? "*CONDUCTIVITY, which the *HEAT TRANSFER step needs"
                               : "*ELECTRICAL CONDUCTIVITY, which the *COUPLED "
                                 "THERMAL-ELECTRICAL step needs"));
  for (double value : *k)
    if (!(value > 0.0))
      throw InputError(material.where, "material " + material.name +
                                           ": conductivities must be positive, got " +
                                           std::to_string(value));
  return {(*k)[0], (*k)[1], (*k)[2]};
}

}  // namespace

bool has_scalar_field_steps(const Model& model) {
  for (const Step& step : model.steps)
    if (step.kind != StepKind::Static) return true;
  return false;
}

ScalarFieldModel prepare_scalar_field_model(const Model& model, const ElementRegistry& registry) {
  ScalarFieldModel prepared;
  const SourceLoc whole_model{model.source, 0};
  if (model.steps.empty())
    throw InputError(whole_model, "the model has no *STEP: there is nothing to analyse");
  if (model.element_count() == 0) throw InputError(whole_model, "the model has no elements");
  const Step& first = model.steps.front();
  for (const Step& step : model.steps)
    if (step.kind != first.kind)
      throw InputError(step.procedure.where,
                       std::string("this ") + procedure_keyword(step.kind) + " step follows a " +
                           procedure_keyword(first.kind) + " step (at " +
                           first.procedure.where.str() +
                           "): Styk runs decks whose steps are all mechanical, all "
                           "*HEAT TRANSFER or all *COUPLED THERMAL-ELECTRICAL");
  prepared.kind = first.kind;
  const bool heat = prepared.kind == StepKind::HeatTransfer;
  prepared.field = heat ? ScalarFieldResult::Kind::Temperature : ScalarFieldResult::Kind::Potential;
  prepared.dof = scalar_dof(prepared.kind);
  refuse_mechanical_features(model, procedure_keyword(prepared.kind));

  const int element_count = model.element_count();
  prepared.formulation.resize(element_count);
  prepared.conductivity.resize(element_count);
  prepared.rule_of_element.resize(element_count);
  prepared.ip_offset.assign(element_count + 1, 0);
  prepared.unknown_of_node.assign(model.node_count(), -1);
  for (int e = 0; e < element_count; ++e) {
    const Element& element = model.elements[e];
    const TElement* formulation = registry.find(element.type);
    if (formulation == nullptr) {
      std::string message =
          element_label(element) + ": no built-in element or plug-in provides this type";
      if (!registry.searched_paths.empty())
        message += " (plug-ins searched in " + registry.searched_paths + ")";
      throw InputError(element.where, message);
    }
    if (formulation->node_count() != element.node_count)
      throw InputError(element.where, element_label(element) + " has " +
                                          std::to_string(element.node_count) + " nodes, " +
                                          std::to_string(formulation->node_count()) + " expected");
    if (element.section < 0 || element.section >= static_cast<int>(model.sections.size()))
      throw InputError(element.where, element_label(element) +
                                          " has no section: add it to an element set named by "
                                          "a *SOLID SECTION");
    if (formulation->node_dofs() != 3)
      throw InputError(element.where, element_label(element) +
                                          " carries rotations (a structural element); steady "
                                          "heat and electric-potential steps take continuum "
                                          "elements only");
    if (formulation->section_measure() == SectionMeasure::Area &&
        !model.sections[element.section].thickness)
      throw InputError(
          model.sections[element.section].where,
          "the *SOLID SECTION of element set " + model.sections[element.section].elset +
              " gives no cross-section area, which " + element_label(element) + " needs");
    prepared.formulation[e] = formulation;
    prepared.conductivity[e] = checked_conductivity(model, element, prepared.kind);

    int rule = -1;
    for (std::size_t r = 0; r < prepared.rules.size(); ++r)
      if (prepared.rules[r].first == formulation) rule = static_cast<int>(r);
    if (rule < 0) {
      IntegrationRule full = formulation->rule(RuleKind::Full);
      if (!rule_resolves_scalar_field(*formulation, full))
        throw InputError(element.where,
                         element_label(element) + " integrates with " + full.label + " (" +
                             std::to_string(full.size()) +
                             " points), too few for a conductance without zero-energy modes; "
                             "use a fully integrated type (e.g. C3D8 for C3D8R)");
      prepared.extrapolations.push_back(make_extrapolation(*formulation, full));
      prepared.rules.emplace_back(formulation, std::move(full));
      rule = static_cast<int>(prepared.rules.size()) - 1;
    }
    prepared.rule_of_element[e] = rule;
    prepared.ip_offset[e + 1] = prepared.ip_offset[e] + prepared.rules[rule].second.size();

    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < element.node_count; ++k) {
      if (nodes[k] < 0 || nodes[k] >= model.node_count())
        throw InputError(element.where, element_label(element) + " refers to an undefined node");
      prepared.unknown_of_node[nodes[k]] = 0;
    }
  }
  for (int n = 0; n < model.node_count(); ++n) {
    if (prepared.unknown_of_node[n] < 0) continue;
    prepared.unknown_of_node[n] = static_cast<int>(prepared.node_of_unknown.size());
    prepared.node_of_unknown.push_back(n);
  }
  return prepared;
}

std::vector<ScalarStepConditions> accumulate_scalar_conditions(const Model& model,
                                                               const ScalarFieldModel& prepared) {
  const std::string field = prepared.dof == 11 ? "temperature" : "potential";
  auto unknown = [&](int node, int dof, const SourceLoc& where, const char* what) {
    if (node < 0 || node >= model.node_count())
      throw InputError(where, std::string(what) + " on an undefined node");
    if (dof != prepared.dof)
      throw InputError(where, std::string(what) + " on dof " + std::to_string(dof) + " of node " +
                                  std::to_string(model.node_ids[node]) + ": this deck's steps " +
                                  "solve for dof " + std::to_string(prepared.dof) + " (" + field +
                                  ")");
    const int u = prepared.unknown_of_node[node];
    if (u < 0)
      throw InputError(where, std::string(what) + " on node " +
                                  std::to_string(model.node_ids[node]) +
                                  ", which belongs to no element");
    return u;
  };
  std::map<int, double> model_level;
  for (const Boundary& b : model.boundaries)
    model_level[unknown(b.node, b.dof, b.where, "boundary condition")] = b.value;
  std::map<int, double> prescribed = model_level;
  std::map<int, double> flows;
  std::map<std::pair<int, int>, double> fluxes;
  std::vector<ScalarStepConditions> out;
  for (const Step& step : model.steps) {
    if (step.boundary_op_new) prescribed = model_level;
    if (step.cflux_op_new) flows.clear();
    if (step.dflux_op_new) fluxes.clear();
    for (const Boundary& b : step.boundaries)
      prescribed[unknown(b.node, b.dof, b.where, "boundary condition")] = b.value;
    for (const ConcentratedLoad& c : step.cfluxes)
      flows[unknown(c.node, c.dof, c.where, "concentrated flow")] = c.value;
    for (const DistributedLoad& d : step.dfluxes) {
      if (d.element < 0 || d.element >= model.element_count())
        throw InputError(d.where, "*DFLUX on an undefined element");
      const int faces = static_cast<int>(prepared.formulation[d.element]->faces().size());
      if (d.face < 1 || d.face > faces)
        throw InputError(d.where, "*DFLUX on face S" + std::to_string(d.face) + " of element " +
                                      std::to_string(model.elements[d.element].id) +
                                      ", which has " + std::to_string(faces) + " faces");
      fluxes[{d.element, d.face - 1}] = d.magnitude;
    }
    ScalarStepConditions conditions;
    conditions.prescribed = prescribed;
    conditions.nodal_flow.assign(prepared.unknowns(), 0.0);
    for (const auto& [u, value] : flows) conditions.nodal_flow[u] = value;
    for (const auto& [key, q] : fluxes)
      conditions.face_fluxes.push_back({key.first, key.second, q});
    out.push_back(std::move(conditions));
  }
  return out;
}

void check_every_part_prescribed(const Model& model, const ScalarFieldModel& prepared,
                                 const ScalarStepConditions& conditions, const Step& step) {
  // Union-find over the unknowns, joined element by element.
  std::vector<int> parent(prepared.unknowns());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int u) {
    while (parent[u] != u) u = parent[u] = parent[parent[u]];
    return u;
  };
  for (int e = 0; e < model.element_count(); ++e) {
    const int* nodes = model.element_nodes(e);
    const int first = root(prepared.unknown_of_node[nodes[0]]);
    for (int k = 1; k < model.elements[e].node_count; ++k)
      parent[root(prepared.unknown_of_node[nodes[k]])] = first;
  }
  std::vector<char> held(prepared.unknowns(), 0);
  for (const auto& entry : conditions.prescribed) held[root(entry.first)] = 1;
  for (int u = 0; u < prepared.unknowns(); ++u)
    if (!held[root(u)])
      throw InputError(step.procedure.where,
                       "no " + std::string(prepared.dof == 11 ? "temperature" : "potential") +
                           " is prescribed (*BOUNDARY, dof " + std::to_string(prepared.dof) +
                           ") on the part of the mesh containing node " +
                           std::to_string(model.node_ids[prepared.node_of_unknown[u]]) +
                           ": its steady field is determined only up to a constant");
}

}  // namespace styk::solver_detail
