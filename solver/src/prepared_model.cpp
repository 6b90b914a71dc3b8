#include "prepared_model.hpp"

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
  if (!material.young || !material.poisson)
    throw InputError(material.where, "material " + material.name +
                                         " has no *ELASTIC constants (Young's modulus and "
                                         "Poisson's ratio are needed for a static analysis)");
  if (!(*material.young > 0.0) || !std::isfinite(*material.young))
    throw InputError(material.where, "material " + material.name +
                                         ": Young's modulus must be positive, got " +
                                         std::to_string(*material.young));
  if (!(*material.poisson > -1.0 && *material.poisson < 0.5))
    throw InputError(material.where, "material " + material.name +
                                         ": Poisson's ratio must lie in (-1, 0.5), got " +
                                         std::to_string(*material.poisson));
  return material;
}

void check_section_measure(const Model& model, const Element& element,
                           const TElement& formulation) {
  const Section& section = model.sections[element.section];
  if (formulation.section_measure() == SectionMeasure::Area && !section.thickness)
    throw InputError(section.where, "the *SOLID SECTION of element set " + section.elset +
                                        " gives no cross-section area (its first data line), "
                                        "which element " + std::to_string(element.id) +
                                        " of type " + element.type + " needs");
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
  prepared.active_of_node.assign(model.node_count(), -1);

  std::vector<const Material*> material_of_section(model.sections.size(), nullptr);
  // Per model node: which displacement components some element stiffens (bit d for direction d).
  std::vector<unsigned char> stiffened_bits(model.node_count(), 0);
  std::vector<char> on_ring(model.node_count(), 0);
  for (int e = 0; e < element_count; ++e) {
    const Element& element = model.elements[e];
    const TElement* formulation = registry.find(element.type);
    if (formulation == nullptr) {
      std::string message = "element " + std::to_string(element.id) + " has type " +
                            element.type + ", which no built-in element or plug-in provides";
      if (!registry.searched_paths.empty())
        message += " (plug-ins searched in " + registry.searched_paths + ")";
      throw InputError(element.where, message);
    }
    if (formulation->node_count() != element.node_count)
      throw InputError(element.where, "element " + std::to_string(element.id) + " of type " +
                                          element.type + " has " +
                                          std::to_string(element.node_count) + " nodes, " +
                                          std::to_string(formulation->node_count()) +
                                          " expected");
    if (element.section < 0 || element.section >= static_cast<int>(model.sections.size()))
      throw InputError(element.where, "element " + std::to_string(element.id) +
                                          " has no section: add it to an element set named "
                                          "by a *SOLID SECTION");
    const Material*& material = material_of_section[element.section];
    if (material == nullptr) material = &checked_material(model, element.section);
    check_section_measure(model, element, *formulation);
    const std::array<bool, 3> active = formulation->active_displacements();
    const unsigned char bits = static_cast<unsigned char>(
        (active[0] ? 1 : 0) | (active[1] ? 2 : 0) | (active[2] ? 4 : 0));
    prepared.formulation[e] = formulation;
    prepared.material[e] = material;

    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < element.node_count; ++k) {
      if (nodes[k] < 0 || nodes[k] >= model.node_count())
        throw InputError(element.where, "element " + std::to_string(element.id) +
                                            " refers to an undefined node");
      prepared.active_of_node[nodes[k]] = 0;
      stiffened_bits[nodes[k]] |= bits;
      if (formulation->form() == ElementForm::Axisymmetric) on_ring[nodes[k]] = 1;
    }
  }

  // Integration points per element, asking each formulation once.
  std::vector<std::pair<const TElement*, int>> rule_sizes;
  for (int e = 0; e < element_count; ++e) {
    int points = -1;
    for (const auto& [formulation, size] : rule_sizes)
      if (formulation == prepared.formulation[e]) points = size;
    if (points < 0) {
      points = prepared.formulation[e]->rule(RuleKind::Full).size();
      rule_sizes.emplace_back(prepared.formulation[e], points);
    }
    prepared.ip_offset[e + 1] = prepared.ip_offset[e] + points;
  }

  for (int n = 0; n < model.node_count(); ++n) {
    if (prepared.active_of_node[n] < 0) continue;
    prepared.active_of_node[n] = static_cast<int>(prepared.node_of_active.size());
    prepared.node_of_active.push_back(n);
    prepared.ring_node.push_back(on_ring[n]);
    for (int d = 0; d < 3; ++d)
      prepared.stiffened.push_back((stiffened_bits[n] >> d) & 1 ? 1 : 0);
  }
  return prepared;
}

std::string describe_dof(const Model& model, const PreparedModel& prepared, int active_dof) {
  static const char* const kDirection[] = {"ux", "uy", "uz"};
  const int node = prepared.node_of_active[active_dof / 3];
  return "node " + std::to_string(model.node_ids[node]) + " (" + kDirection[active_dof % 3] + ")";
}

}  // namespace styk::solver_detail
