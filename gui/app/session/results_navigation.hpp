// Results navigation (issue 7): the increments of a multi-step analysis by name, the fields an
// increment can draw, and one node's value over the load history (the "value vs increment" X-Y
// chart). Values come from render::evaluate_field, the renderer's single reading of the results.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "styk/core/results.hpp"
#include "styk/render/field.hpp"

namespace styk::gui {

// "step 2, increment 3, time 0.6" (the total time over the steps, 6 significant digits).
std::string increment_label(const IncrementResult& increment);
std::vector<std::string> increment_labels(const Results& results);

// The render::field_names() entries this increment holds data for, in that order: U.* and RF.*
// with displacements, S.* and E.* with any stress or strain array (the averaging decides which
// one is drawn), the contact fields with contact output, and any other field (e.g. a scalar
// field such as NT) when it evaluates.
std::vector<std::string> available_fields(const Model& model, const IncrementResult& increment);

struct HistoryPoint {
  int increment = 0;  // index into Results::increments
  double time = 0.0;  // total time
  double value = 0.0;
};

// The field at one node (index) over every increment that holds it: node fields directly (where
// defined, e.g. CPRESS at slave nodes only), element-node and element fields as the mean over the
// elements using the node. Increments without the field are left out. Throws InputError for an
// unknown field name or a node index out of range.
std::vector<HistoryPoint> node_history(const Model& model, const Results& results, int node,
                                       const std::string& field, render::Averaging averaging);

// The value of an evaluated field at a node (as node_history, for one increment); empty where the
// field is not defined. `elements_of_node`: the elements using the node.
std::optional<double> field_at_node(const Model& model, const render::ScalarField& field, int node,
                                    const std::vector<int>& elements_of_node);

// The value of an evaluated field for an element: element fields directly, element-node fields
// as the mean over its nodes, node fields as the mean over its nodes where defined.
std::optional<double> field_at_element(const Model& model, const render::ScalarField& field,
                                       int element);

}  // namespace styk::gui
