#include "session/results_navigation.hpp"

#include <cstdio>

#include "styk/core/diagnostics.hpp"

namespace styk::gui {
namespace {

std::string quantity_of(const std::string& name) {
  return to_upper(name.substr(0, name.find('.')));
}

bool holds_tensor(const IncrementResult& inc, bool stress) {
  return stress ? !(inc.S_nodal_II.empty() && inc.S_nodal_I.empty() && inc.S_centroid.empty() &&
                    inc.S_element_nodes.empty())
                : !(inc.E_nodal_II.empty() && inc.E_nodal_I.empty() && inc.E_centroid.empty() &&
                    inc.E_element_nodes.empty());
}

std::vector<int> elements_using(const Model& model, int node) {
  std::vector<int> elements;
  for (int e = 0; e < model.element_count(); ++e) {
    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < model.elements[e].node_count; ++k)
      if (nodes[k] == node) {
        elements.push_back(e);
        break;
      }
  }
  return elements;
}

}  // namespace

std::string increment_label(const IncrementResult& increment) {
  char buffer[120];
  std::snprintf(buffer, sizeof buffer, "step %d, increment %d, time %.6g", increment.step,
                increment.increment, increment.total_time);
  return buffer;
}

std::vector<std::string> increment_labels(const Results& results) {
  std::vector<std::string> labels;
  for (const IncrementResult& inc : results.increments) labels.push_back(increment_label(inc));
  return labels;
}

std::vector<std::string> available_fields(const Model& model, const IncrementResult& increment) {
  const bool displacements = increment.U.size() == model.coords.size() && !increment.U.empty();
  std::vector<std::string> names;
  for (const std::string& name : render::field_names()) {
    const std::string q = quantity_of(name);
    bool held = false;
    if (q == "U" || q == "RF")
      held = displacements;
    else if (q == "S" || q == "E")
      held = holds_tensor(increment, q == "S");
    else if (q.size() > 1 && q[0] == 'C' &&
             (q == "CPRESS" || q == "CSHEAR" || q == "CSLIP" || q == "CGAP" || q == "CSTATUS"))
      held = !increment.contact.empty();
    else {
      // A field this code does not know by name (e.g. a scalar field): ask the renderer.
      try {
        render::evaluate_field(model, increment, name, render::Averaging::MethodII);
        held = true;
      } catch (const InputError&) {
        held = false;
      }
    }
    if (held) names.push_back(name);
  }
  return names;
}

std::optional<double> field_at_node(const Model& model, const render::ScalarField& field, int node,
                                    const std::vector<int>& elements_of_node) {
  if (field.location == render::FieldLocation::Node) {
    if (node >= int(field.values.size()) || !field.defined_at(node)) return std::nullopt;
    return field.values[node];
  }
  double sum = 0.0;
  int count = 0;
  for (int e : elements_of_node) {
    const Element& el = model.elements[e];
    if (field.location == render::FieldLocation::Element) {
      sum += field.values[e];
      ++count;
      continue;
    }
    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < el.node_count; ++k)
      if (nodes[k] == node) sum += field.values[el.first_node + k], ++count;
  }
  if (count == 0) return std::nullopt;
  return sum / count;
}

std::optional<double> field_at_element(const Model& model, const render::ScalarField& field,
                                       int element) {
  if (element < 0 || element >= model.element_count()) return std::nullopt;
  const Element& el = model.elements[element];
  if (field.location == render::FieldLocation::Element) return field.values[element];
  double sum = 0.0;
  int count = 0;
  const int* nodes = model.element_nodes(element);
  for (int k = 0; k < el.node_count; ++k) {
    if (field.location == render::FieldLocation::ElementNode) {
      sum += field.values[el.first_node + k], ++count;
    } else if (field.defined_at(nodes[k])) {
      sum += field.values[nodes[k]], ++count;
    }
  }
  if (count == 0) return std::nullopt;
  return sum / count;
}

std::vector<HistoryPoint> node_history(const Model& model, const Results& results, int node,
                                       const std::string& field, render::Averaging averaging) {
  if (node < 0 || node >= model.node_count())
    throw InputError({}, "node index " + std::to_string(node) + " is not in the model");
  const std::vector<int> elements = elements_using(model, node);
  std::vector<HistoryPoint> points;
  std::optional<InputError> first_error;
  bool evaluated = false;
  for (std::size_t i = 0; i < results.increments.size(); ++i) {
    const IncrementResult& inc = results.increments[i];
    std::optional<double> value;
    try {
      value = field_at_node(model, render::evaluate_field(model, inc, field, averaging), node,
                            elements);
      evaluated = true;
    } catch (const InputError& e) {
      if (!first_error) first_error = e;
      continue;  // this increment does not hold the field (e.g. no contact output yet)
    }
    if (value) points.push_back({int(i), inc.total_time, *value});
  }
  // An unknown name, or a field no increment holds: the renderer's message says which.
  if (!evaluated && first_error) throw *first_error;
  return points;
}

}  // namespace styk::gui
