// New layers from the view's filter or selection (issue 7, SPEC §5 "layers built from sets or by
// hand"): the chosen elements become an element set NAME and NAME a user layer (layers.hpp), shown,
// hidden and coloured like the part layers, as one undoable edit. A new set changes neither the
// mesh nor the analysis, so results on display stay attached.
#pragma once

#include <string>
#include <vector>

#include "session/document.hpp"
#include "session/element_filter.hpp"
#include "session/selection.hpp"

namespace styk::gui {

// The elements a selection stands for: picked elements, the elements of picked faces, or for
// picked nodes the elements whose nodes are all picked. Ascending, unique.
std::vector<int> elements_of_selection(const Model& model, const Selection& selection);

// Adds element set NAME (upper-case) with `elements` (indices) and makes it a user layer.
// InputError (nothing changed) for a bad or taken name, no elements, or an index out of range.
void add_layer(Document& document, const std::string& name, const std::vector<int>& elements);
// The elements passing `filter`; refused when the filter is inactive (it would be every element).
void add_layer_from_filter(Document& document, const std::string& name,
                           const ElementDisplayFilter& filter);
void add_layer_from_selection(Document& document, const std::string& name,
                              const Selection& selection);

}  // namespace styk::gui
