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
  // 1: claimed by a user layer, 2: by a part layer.
  std::vector<char> taken(model.elements.size(), 0);
  for (const std::string& name : user_layers_) {
    const ElementSet* set = model.find_elset(name);
    if (!set) continue;
    render::Layer layer;
    layer.name = set->name;
    for (int e : set->elements)
      if (!taken[e]) layer.elements.push_back(e), taken[e] = 1;
    if (!layer.elements.empty()) layers.push_back(std::move(layer));
  }
  // Sets that may be parts (user layers are not), for "a set covering the whole model".
  std::size_t part_sets = 0;
  for (const auto& [name, set] : model.elsets) part_sets += is_user_layer(name) ? 0 : 1;
  for (const ElementSet* set : candidate_sets(model)) {
    if (set->elements.empty() || is_user_layer(set->name)) continue;
    // A set covering the whole model is no part when other sets exist (e.g. EALL next to parts).
    const bool whole = set->elements.size() == model.elements.size();
    const bool overlaps = std::any_of(set->elements.begin(), set->elements.end(),
                                      [&](int e) { return taken[e] == 2; });
    if (overlaps || (whole && model.sections.empty() && part_sets > 1)) continue;
    render::Layer layer;
    layer.name = set->name;
    for (int e : set->elements)
      if (!taken[e]) layer.elements.push_back(e), taken[e] = 2;
    if (!layer.elements.empty()) layers.push_back(std::move(layer));
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

bool LayerTable::is_user_layer(const std::string& name) const {
  return std::find(user_layers_.begin(), user_layers_.end(), name) != user_layers_.end();
}

void LayerTable::add_user_layer(const std::string& name) {
  if (!is_user_layer(name)) user_layers_.push_back(name);
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
  return std::any_of(layers_.begin(), layers_.end(),
                     [](const render::Layer& l) { return l.visible && !l.elements.empty(); });
}

}  // namespace styk::gui
