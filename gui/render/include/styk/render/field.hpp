// Scalar fields the renderer colours the model with, taken from one increment of the results
// (SPEC §5): nodal vectors (U, RF: magnitude or component) and stress/strain tensors (components,
// Mises, principal values) at the averaging the user asks for. The renderer never recomputes what
// the solver stored: averaging picks one of the recovered arrays of IncrementResult.
#pragma once

#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::render {

// How element values become a picture (SPEC §5):
//  None      unaveraged element-node values (S_element_nodes): jumps between elements stay visible
//  MethodI   per node, the mean of the element-node values (S_nodal_I)
//  MethodII  per node, the mean of the centroid values of the elements around it (S_nodal_II)
//  Centroid  one value per element (S_centroid), drawn flat
enum class Averaging { None, MethodI, MethodII, Centroid };

// "none", "I", "II", "centroid" (case-insensitive); InputError otherwise.
Averaging parse_averaging(const std::string& text);
std::string averaging_name(Averaging averaging);

// Where the values of a field live.
enum class FieldLocation {
  Node,         // values[node index]
  ElementNode,  // values[elements[e].first_node + k], the layout of Model::connectivity
  Element,      // values[element index]
};

struct ScalarField {
  std::string name;         // canonical name, e.g. "S.mises"
  std::string description;  // for the title block, e.g. "S.mises, averaging II"
  FieldLocation location = FieldLocation::Node;
  bool uses_averaging = false;  // tensor fields do; U and RF do not
  std::vector<double> values;
};

// Every field name evaluate_field() accepts, for messages and `--help`.
std::vector<std::string> field_names();

// Evaluates field `name` (e.g. "U", "U.z", "RF.mag", "S.mises", "S.p1", "E.11") of `increment`.
// Throws InputError naming the accepted fields when `name` is unknown, and naming the data the
// increment does hold when the requested array is empty (e.g. averaging II asked for, but the
// solver stored no S_nodal_II). Contact fields (CPRESS, CSLIP, CSTATUS) are recognised and
// rejected with the reason: the results schema does not hold contact output yet.
ScalarField evaluate_field(const Model& model, const IncrementResult& increment,
                           const std::string& name, Averaging averaging);

// Largest displacement magnitude over the given nodes (all nodes when `nodes` is empty).
double max_displacement(const IncrementResult& increment, const std::vector<int>& nodes);

}  // namespace styk::render
