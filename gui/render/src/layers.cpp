#include "styk/render/layers.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <sstream>

#include "styk/core/diagnostics.hpp"

namespace styk::render {
namespace {

Id parse_id(const std::string& text, const std::string& whole) {
  errno = 0;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE)
    throw InputError({}, "bad element id range '" + whole + "'; write FIRST-LAST, e.g. 100-250");
  return static_cast<Id>(value);
}

}  // namespace

bool ElementFilter::accepts(const Element& element) const {
  if (element.id < id_min || element.id > id_max) return false;
  return types.empty() || std::find(types.begin(), types.end(), element.type) != types.end();
}

ElementFilter parse_element_filter(const std::string& id_range, const std::string& types) {
  ElementFilter filter;
  if (!id_range.empty()) {
    const std::size_t dash = id_range.find('-', 1);  // a leading '-' would be a sign, ids are > 0
    if (dash == std::string::npos) {
      filter.id_min = filter.id_max = parse_id(id_range, id_range);
    } else {
      const std::string first = id_range.substr(0, dash), last = id_range.substr(dash + 1);
      if (!first.empty()) filter.id_min = parse_id(first, id_range);
      if (!last.empty()) filter.id_max = parse_id(last, id_range);
    }
    if (filter.id_min > filter.id_max)
      throw InputError({}, "element id range '" + id_range + "' is empty (first > last)");
  }
  std::stringstream list(types);
  std::string type;
  while (std::getline(list, type, ','))
    if (!type.empty()) filter.types.push_back(to_upper(type));
  return filter;
}

Rgb layer_palette(int i) {
  static constexpr std::array<Rgb, 8> kPalette = {{
      {0.62f, 0.70f, 0.84f},  // steel blue
      {0.86f, 0.74f, 0.52f},  // tan
      {0.66f, 0.82f, 0.60f},  // sage
      {0.86f, 0.60f, 0.66f},  // rose
      {0.74f, 0.66f, 0.86f},  // lavender
      {0.80f, 0.80f, 0.56f},  // olive
      {0.58f, 0.80f, 0.80f},  // teal
      {0.80f, 0.68f, 0.62f},  // clay
  }};
  return kPalette[static_cast<std::size_t>(i) % kPalette.size()];
}

Layer whole_model_layer(const Model& model) {
  Layer layer{"ALL", {}, layer_palette(0), true};
  layer.elements.resize(model.elements.size());
  for (std::size_t e = 0; e < model.elements.size(); ++e) layer.elements[e] = static_cast<int>(e);
  return layer;
}

std::vector<Layer> layers_from_sets(const Model& model, const std::vector<std::string>& names) {
  std::vector<Layer> layers;
  for (const std::string& name : names) {
    const ElementSet* set = model.find_elset(name);
    if (!set) {
      std::string known;
      for (const auto& entry : model.elsets) known += (known.empty() ? "" : ", ") + entry.first;
      throw InputError({}, "no element set '" + name + "' to show as a layer; element sets: " +
                               (known.empty() ? std::string("(none)") : known));
    }
    layers.push_back(
        Layer{set->name, set->elements, layer_palette(static_cast<int>(layers.size())), true});
  }
  return layers;
}

std::vector<int> filter_elements(const Model& model, const std::vector<int>& elements,
                                 const ElementFilter& filter) {
  std::vector<int> kept;
  kept.reserve(elements.size());
  for (int e : elements)
    if (filter.accepts(model.elements[e])) kept.push_back(e);
  return kept;
}

Layer layer_from_filter(const Model& model, const std::string& name, const ElementFilter& filter,
                        int palette_index) {
  return Layer{name, filter_elements(model, whole_model_layer(model).elements, filter),
               layer_palette(palette_index), true};
}

}  // namespace styk::render
