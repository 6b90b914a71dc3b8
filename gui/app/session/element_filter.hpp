// The view's element filter (issue 7, SPEC §5 "filter elements by number or type"): only the
// elements whose id lies in one of the ranges ("1-500, 700") and whose type is one of the chosen
// types are drawn. The skin is built from the passing elements alone, so the faces of the cut
// through the model show. The filter is a display setting: it changes no model data.
#pragma once

#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/render/layers.hpp"

namespace styk::gui {

struct IdRange {
  Id first = 0;
  Id last = 0;  // inclusive
};

struct ElementDisplayFilter {
  std::vector<IdRange> ranges;     // empty: every id
  std::vector<std::string> types;  // upper-case; empty: every type

  bool active() const { return !ranges.empty() || !types.empty(); }
  bool accepts(const Element& element) const;
};

// Parses "1-500, 700 ,900-950" (commas and/or spaces between items; "a-b" inclusive with a <= b;
// ids >= 1). Empty text: every id. Throws InputError naming the bad item.
std::vector<IdRange> parse_id_ranges(const std::string& text);
// The text parse_id_ranges() reads back ("1-500, 700").
std::string format_id_ranges(const std::vector<IdRange>& ranges);

// The element types the model holds, sorted (the dialog's check boxes).
std::vector<std::string> element_types_present(const Model& model);

// Builds a filter and refuses (InputError) bad range text, a type the model does not hold, and a
// filter no element of the model passes (an empty view would look like a bug).
ElementDisplayFilter make_element_filter(const Model& model, const std::string& ranges,
                                         const std::vector<std::string>& types);

// Indices of the elements passing the filter, ascending (every element when inactive).
std::vector<int> filtered_elements(const Model& model, const ElementDisplayFilter& filter);
// The layers with only their passing elements (same names, colours, visibility).
std::vector<render::Layer> filter_layers(const Model& model,
                                         const std::vector<render::Layer>& layers,
                                         const ElementDisplayFilter& filter);

}  // namespace styk::gui
