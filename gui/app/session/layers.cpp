#include "session/layers.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace styk::gui {
namespace {

// Element sets in the order layers take them: section sets first (those are the parts), then, when
// the model has no section, every element set by name.
std::vector<const ElementSet*> candidate_sets(const Model& model) {
  std::vector<const ElementSet*> sets;
  for (const Section& s : model.sections)
    if (const ElementSet* set = model.find_elset(s.elset)) sets.push_back(set);
  if (sets.empty())
    for (const auto& [name, set] : model.elsets) sets.push_back(&set);
  return sets;
}

}  // namespace

void LayerTable::rebuild(const Model& model) {
  std::map<std::string, render::Layer> previous;
  for (const render::Layer& l : layers_) previous[l.name] = l;

  std::vector<render::Layer> layers;
  std::vector<char> taken(model.elements.size(), 0);
  for (const ElementSet* set : candidate_sets(model)) {
    if (set->elements.empty()) continue;
    // A set covering the whole model is no part when other sets exist (e.g. EALL next to parts).
    const bool whole = set->elements.size() == model.elements.size();
    const bool overlaps = std::any_of(set->elements.begin(), set->elements.end(),
                                      [&](int e) { return taken[e] != 0; });
    if (overlaps || (whole && model.sections.empty() && model.elsets.size() > 1)) continue;
    render::Layer layer;
    layer.name = set->name;
    layer.elements = set->elements;
    for (int e : set->elements) taken[e] = 1;
    layers.push_back(std::move(layer));
  }
  std::vector<int> rest;
  for (std::size_t e = 0; e < taken.size(); ++e)
    if (!taken[e]) rest.push_back(static_cast<int>(e));
  if (!rest.empty()) {
    render::Layer layer;
    layer.name = layers.empty() ? "ALL" : "OTHER";
    layer.elements = std::move(rest);
    layers.push_back(std::move(layer));
  }
  for (std::size_t i = 0; i < layers.size(); ++i) {
    layers[i].color = render::layer_palette(static_cast<int>(i));
    const auto it = previous.find(layers[i].name);
    if (it != previous.end()) {
      layers[i].visible = it->second.visible;
      layers[i].color = it->second.color;
    }
  }
  layers_ = std::move(layers);
}

render::Layer& LayerTable::find(const std::string& name) {
  for (render::Layer& l : layers_)
    if (l.name == name) return l;
  throw std::out_of_range("no layer " + name);
}

const render::Layer& LayerTable::layer(const std::string& name) const {
  for (const render::Layer& l : layers_)
    if (l.name == name) return l;
  throw std::out_of_range("no layer " + name);
}

void LayerTable::set_visible(const std::string& name, bool visible) {
  find(name).visible = visible;
}

void LayerTable::set_color(const std::string& name, const render::Rgb& color) {
  find(name).color = color;
}

bool LayerTable::any_visible() const {
  return std::any_of(layers_.begin(), layers_.end(), [](const render::Layer& l) {
    return l.visible && !l.elements.empty();
  });
}

}  // namespace styk::gui
