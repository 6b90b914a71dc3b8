#include "session/layer_edits.hpp"

#include <algorithm>

#include "session/input_checks.hpp"

namespace styk::gui {

std::vector<int> elements_of_selection(const Model& model, const Selection& selection) {
  std::vector<int> elements;
  switch (selection.kind()) {
    case PickKind::Element:
      elements = selection.elements();
      break;
    case PickKind::Face:
      for (const SurfaceFace& f : selection.faces()) elements.push_back(f.element);
      break;
    case PickKind::Node: {
      std::vector<char> picked(model.coords.size(), 0);
      for (int n : selection.nodes())
        if (n >= 0 && n < static_cast<int>(picked.size())) picked[n] = 1;
      for (int e = 0; e < model.element_count(); ++e) {
        const int* nodes = model.element_nodes(e);
        const int count = model.elements[e].node_count;
        if (std::all_of(nodes, nodes + count, [&](int n) { return picked[n] != 0; }))
          elements.push_back(e);
      }
      break;
    }
  }
  std::sort(elements.begin(), elements.end());
  elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
  return elements;
}

void add_layer(Document& document, const std::string& name, const std::vector<int>& elements) {
  check_name(name, "the layer");
  const std::string upper = to_upper(name);
  const Model& model = document.model();
  check_set_names_free(model, upper);
  if (elements.empty()) refuse("the layer " + upper + " would hold no element");
  for (int e : elements)
    if (e < 0 || e >= model.element_count())
      refuse("element index " + std::to_string(e) + " is not in the model (select again)");
  ElementSet set;
  set.name = upper;
  set.elements = elements;
  std::sort(set.elements.begin(), set.elements.end());
  set.elements.erase(std::unique(set.elements.begin(), set.elements.end()), set.elements.end());
  document.layers().add_user_layer(upper);
  document.apply(make_model_edit(
      "New layer " + upper, [set](Model& m) { m.elsets[set.name] = set; },
      [upper](Model& m) { m.elsets.erase(upper); }, /*keeps_results=*/true));
}

void add_layer_from_filter(Document& document, const std::string& name,
                           const ElementDisplayFilter& filter) {
  if (!filter.active())
    refuse("no filter is set: choose element ids or types in View > Filter first");
  add_layer(document, name, filtered_elements(document.model(), filter));
}

void add_layer_from_selection(Document& document, const std::string& name,
                              const Selection& selection) {
  if (selection.empty()) refuse("nothing is selected: pick elements, faces or nodes first");
  const std::vector<int> elements = elements_of_selection(document.model(), selection);
  if (elements.empty())
    refuse("the picked nodes hold no whole element: pick elements, or every node of one");
  add_layer(document, name, elements);
}

}  // namespace styk::gui
