// What is visible: layers (element sets from the deck, or sets made by a filter), each shown or
// hidden with its own colour, and an element filter by id range and type (SPEC §5).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/render/color.hpp"

namespace styk::render {

struct ElementFilter {
  Id id_min = std::numeric_limits<Id>::min();
  Id id_max = std::numeric_limits<Id>::max();
  std::vector<std::string> types;  // upper-case type names; empty = every type

  bool accepts(const Element& element) const;
};

// Parses "--elements 100-250" (or a single id "7", or "100-" / "-250") and "--types C3D20,C3D21".
// Empty strings accept everything. InputError on malformed text.
ElementFilter parse_element_filter(const std::string& id_range, const std::string& types);

struct Layer {
  std::string name;
  std::vector<int> elements;  // element indices, sorted, unique
  Rgb color;
  bool visible = true;
};

// The i-th layer colour: muted, distinct from each other and from the contour rainbow's pure hues.
Rgb layer_palette(int i);

// One layer holding every element of the model, named "ALL".
Layer whole_model_layer(const Model& model);
// One layer per element set name (case-insensitive), coloured in order. An unknown name is an
// InputError listing the element sets the model has.
std::vector<Layer> layers_from_sets(const Model& model, const std::vector<std::string>& names);
// A layer made by a filter over the whole model.
Layer layer_from_filter(const Model& model, const std::string& name, const ElementFilter& filter,
                        int palette_index);
// The elements of `elements` that pass `filter`.
std::vector<int> filter_elements(const Model& model, const std::vector<int>& elements,
                                 const ElementFilter& filter);

}  // namespace styk::render
