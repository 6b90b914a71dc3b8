#include "prepared_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace styk::solver_detail {
namespace {

const Material& checked_material(const Model& model, int section_index) {
  const Section& section = model.sections[section_index];
  if (section.material_index < 0 ||
      section.material_index >= static_cast<int>(model.materials.size()))
    throw InputError(section.where, "the section of element set " + section.elset +
                                        " refers to an undefined material " + section.material);
  const Material& material = model.materials[section.material_index];
  if (!material.has_elasticity())
    throw InputError(material.where, "material " + material.name +
                                         " has no *ELASTIC constants (Young's modulus and "
                                         "Poisson's ratio are needed for a static analysis)");
  check_elasticity(material);  // E, nu in range; tables positive definite at every temperature
  return material;
}

void check_section_measure(const Model& model, const Element& element,
                           const TElement& formulation) {
  const Section& section = model.sections[element.section];
  const bool beam_type = formulation.section_measure() == SectionMeasure::Beam;
  if (beam_type && !section.beam)
    throw InputError(section.where, "element " + std::to_string(element.id) + " of element set " +
                                        section.elset + " is a beam (" + element.type +
                                        "): it takes a *BEAM SECTION, not a *SOLID SECTION");
  if (!beam_type && section.beam)
    throw InputError(section.where, "the *BEAM SECTION of element set " + section.elset +
                                        " covers element " + std::to_string(element.id) +
                                        " of type " + element.type +
                                        ", which is not a beam; use *SOLID SECTION");
  const bool shell_type = formulation.section_measure() == SectionMeasure::Shell;
  if (shell_type != section.shell.has_value())
    throw InputError(section.where, "element " + std::to_string(element.id) + " (" + element.type +
                                        ") of element set " + section.elset +
                                        (shell_type ? " is a shell: it takes a *SHELL SECTION"
                                                    : " is not a shell: a *SHELL SECTION "
                                                      "cannot cover it"));
  if (formulation.section_measure() == SectionMeasure::Area && !section.thickness)
    throw InputError(section.where, "the *SOLID SECTION of element set " + section.elset +
                                        " gives no cross-section area (its first data line), "
                                        "which element " +
                                        std::to_string(element.id) + " of type " + element.type +
                                        " needs");
  // A bar's uniaxial law is isotropic: a direction-dependent one would need the bar's axis in
  // the material axes.
  const Material& material = model.materials[section.material_index];
  const bool isotropic = material.elastic_type == ElasticType::Isotropic &&
                         material.expansion_type == ExpansionType::Isotropic;
  if (formulation.section_measure() == SectionMeasure::Area && !isotropic)
    throw InputError(section.where, "element set " + section.elset + " holds " + element.type +
                                        " elements (bars), which take an isotropic material "
                                        "only; material " +
                                        material.name + " is orthotropic or anisotropic");
  // A beam integrates its section with one E and nu: a constant isotropic law.
  const bool constant = material.young && material.poisson && material.elastic_table.empty() &&
                        material.expansion_table.empty();
  if (formulation.section_measure() == SectionMeasure::Beam && !(isotropic && constant))
    throw InputError(section.where, "element set " + section.elset + " holds " + element.type +
                                        " elements (beams), which take a constant isotropic "
                                        "material (one *ELASTIC line E, nu; one *EXPANSION "
                                        "line); material " +
                                        material.name + " is not");
}

// The rule element e integrates with: its section's choice for beams, the standard one else.
RuleKind section_rule(const Model& model, int e) {
  const Section& section = model.sections[model.elements[e].section];
  if (section.beam && section.beam->integration == BeamIntegration::Reduced)
    return RuleKind::Reduced;
  return RuleKind::Full;
}

}  // namespace

double cross_section_of(const Model& model, int e) {
  const int section = model.elements[e].section;
  if (section < 0 || section >= static_cast<int>(model.sections.size())) return 1.0;
  return model.sections[section].thickness.value_or(1.0);
}

PreparedModel prepare_model(const Model& model, const ElementRegistry& registry) {
  PreparedModel prepared;
  const int element_count = model.element_count();
  prepared.formulation.resize(element_count);
  prepared.material.resize(element_count);
  prepared.ip_offset.assign(element_count + 1, 0);
  prepared.station_offset.assign(element_count + 1, 0);
  prepared.rule_kind.assign(element_count, RuleKind::Full);
  prepared.active_of_node.assign(model.node_count(), -1);

  std::vector<const Material*> material_of_section(model.sections.size(), nullptr);
  // Per model node: which dofs some element stiffens (bit d for component d) and how many dofs
  // its elements carry per node.
  std::vector<unsigned char> stiffened_bits(model.node_count(), 0);
  std::vector<unsigned char> dofs_of_node(model.node_count(), 0);
  std::vector<char> on_ring(model.node_count(), 0);
  for (int e = 0; e < element_count; ++e) {
    const Element& element = model.elements[e];
    const TElement* formulation = registry.find(element.type);
    if (formulation == nullptr) {
      std::string message = "element " + std::to_string(element.id) + " has type " + element.type +
                            ", which no built-in element or plug-in provides";
      if (!registry.searched_paths.empty())
        message += " (plug-ins searched in " + registry.searched_paths + ")";
      throw InputError(element.where, message);
    }
    if (formulation->node_count() != element.node_count)
      throw InputError(element.where, "element " + std::to_string(element.id) + " of type " +
                                          element.type + " has " +
                                          std::to_string(element.node_count) + " nodes, " +
                                          std::to_string(formulation->node_count()) + " expected");
    if (element.section < 0 || element.section >= static_cast<int>(model.sections.size()))
      throw InputError(element.where, "element " + std::to_string(element.id) +
                                          " has no section: add it to an element set named "
                                          "by a *SOLID SECTION");
    const Material*& material = material_of_section[element.section];
    if (material == nullptr) material = &checked_material(model, element.section);
    check_section_measure(model, element, *formulation);
    prepared.rule_kind[e] = section_rule(model, e);
    const int node_dofs = formulation->node_dofs();
    if (node_dofs != 3 && node_dofs != kMaxNodeDofs)
      throw InputError(element.where, "element type " + element.type + " declares " +
                                          std::to_string(node_dofs) +
                                          " dofs per node; Styk supports 3 (displacements) or 6 "
                                          "(displacements and rotations)");
    const DofSet active = formulation->active_dofs();
    unsigned char bits = 0;
    for (int d = 0; d < node_dofs; ++d)
      if (active[d]) bits = static_cast<unsigned char>(bits | (1u << d));
    prepared.formulation[e] = formulation;
    prepared.material[e] = material;

    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < element.node_count; ++k) {
      if (nodes[k] < 0 || nodes[k] >= model.node_count())
        throw InputError(element.where,
                         "element " + std::to_string(element.id) + " refers to an undefined node");
      prepared.active_of_node[nodes[k]] = 0;
      stiffened_bits[nodes[k]] |= bits;
      dofs_of_node[nodes[k]] =
          std::max(dofs_of_node[nodes[k]], static_cast<unsigned char>(node_dofs));
      if (formulation->form() == ElementForm::Axisymmetric) on_ring[nodes[k]] = 1;
    }
  }

  // Nodes that only constraints use (a coupling's reference node, a pre-tension node, the nodes
  // an *EQUATION names outside the mesh) carry the dofs their equations name.
  for (const Equation& equation : model.equations)
    for (const EquationTerm& term : equation.terms) {
      if (term.node < 0 || term.node >= model.node_count() || term.dof < 1 || term.dof > 3)
        continue;  // EquationElimination reports it
      prepared.active_of_node[term.node] = 0;
      stiffened_bits[term.node] |= static_cast<unsigned char>(1 << (term.dof - 1));
      dofs_of_node[term.node] = std::max(dofs_of_node[term.node], static_cast<unsigned char>(3));
    }

  // Integration points and stations per element, asking each formulation and rule once.
  struct RuleSize {
    const TElement* formulation;
    RuleKind kind;
    int points, stations;
  };
  std::vector<RuleSize> rule_sizes;
  for (int e = 0; e < element_count; ++e) {
    const TElement* formulation = prepared.formulation[e];
    const RuleKind kind = prepared.rule_kind[e];
    auto known = std::find_if(rule_sizes.begin(), rule_sizes.end(), [&](const RuleSize& r) {
      return r.formulation == formulation && r.kind == kind;
    });
    if (known == rule_sizes.end())
      known = rule_sizes.insert(
          rule_sizes.end(),
          {formulation, kind, formulation->rule(kind).size(), formulation->section_stations(kind)});
    prepared.ip_offset[e + 1] = prepared.ip_offset[e] + known->points;
    prepared.station_offset[e + 1] = prepared.station_offset[e] + known->stations;
  }

  prepared.dof_offset.push_back(0);
  for (int n = 0; n < model.node_count(); ++n) {
    if (prepared.active_of_node[n] < 0) continue;
    const int a = static_cast<int>(prepared.node_of_active.size());
    prepared.active_of_node[n] = a;
    prepared.node_of_active.push_back(n);
    prepared.ring_node.push_back(on_ring[n]);
    for (int d = 0; d < dofs_of_node[n]; ++d) {
      prepared.stiffened.push_back((stiffened_bits[n] >> d) & 1 ? 1 : 0);
      prepared.node_of_dof.push_back(a);
    }
    prepared.dof_offset.push_back(prepared.dof_offset.back() + dofs_of_node[n]);
  }
  prepared.shell_normals = resolve_shell_normals(model, prepared.formulation);
  return prepared;
}

void PreparedModel::element_dofs(const Model& model, int e, std::vector<int>& dofs) const {
  const int n = model.elements[e].node_count;
  const int per_node = formulation[e]->node_dofs();
  const int* nodes = model.element_nodes(e);
  dofs.resize(static_cast<std::size_t>(n) * per_node);
  for (int k = 0; k < n; ++k) {
    const int first = dof_offset[active_of_node[nodes[k]]];
    for (int c = 0; c < per_node; ++c) dofs[k * per_node + c] = first + c;
  }
}

void check_output_requests(const Model& model, const PreparedModel& prepared) {
  const bool stations = prepared.station_offset.back() > 0;
  for (const Step& step : model.steps)
    for (const OutputRequest& request : step.outputs)
      for (const std::string& var : request.vars) {
        if ((var == "UR" || var == "RM") && !prepared.has_rotations())
          throw InputError(request.where,
                           "output variable " + var +
                               " needs nodes with rotations (beam or shell elements); no "
                               "node of this model carries any");
        if ((var == "SF" || var == "SM") && !stations)
          throw InputError(request.where, "output variable " + var +
                                              " (section forces and moments) needs beam or "
                                              "shell elements; this model has none");
        const bool energy = var == "ENER" || var == "ELSE" || var == "EVOL" || var == "THE";
        if (energy && stations)
          throw InputError(request.where, "output variable " + var +
                                              " is not computed for beam and shell elements "
                                              "(their section is integrated in resultants); this "
                                              "model has some");
      }
}

std::string describe_dof(const Model& model, const PreparedModel& prepared, int active_dof) {
  static const char* const kComponent[] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  const int node = prepared.node_of_active[prepared.node_of(active_dof)];
  return "node " + std::to_string(model.node_ids[node]) + " (" +
         kComponent[prepared.component(active_dof)] + ")";
}

}  // namespace styk::solver_detail
