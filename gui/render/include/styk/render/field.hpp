// Scalar fields the renderer colours the model with, taken from one increment of the results
// (SPEC §5): nodal vectors (U, RF: magnitude or component), stress/strain tensors (components,
// Mises, principal values) at the averaging the user asks for, and contact output at the slave
// nodes (pressure, shear, slip, gap, and the status as a discrete field). The renderer never
// recomputes what the solver stored: averaging picks one of the recovered arrays of
// IncrementResult.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/render/color_scale.hpp"

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

// The fibre of a shell whose values colour it (docs/render.md "Shells"): the output points of a
// shell are its surface Gauss points at the bottom, middle and top fibre (docs/elements.md).
enum class ShellFibre { Bottom = 0, Middle = 1, Top = 2 };
// "bottom", "middle", "top"; parse_shell_fibre throws InputError for another name.
std::string shell_fibre_name(ShellFibre fibre);
ShellFibre parse_shell_fibre(const std::string& name);

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
  // Node fields only: per node, 1 where the field has a value (contact fields: the slave nodes).
  // Empty: defined everywhere. A face is drawn with the field only when every one of its nodes
  // has a value; the others are drawn neutral grey (or left out, GeometryRequest).
  std::vector<char> defined;
  // Non-empty: a discrete field whose values are indices into these names (CSTATUS: open, stick,
  // slip); drawn one colour per category, each face node's colour over its share of the face.
  std::vector<std::string> categories;
  // A field that lives on surfaces (contact output). `normals` (per node, where defined): the
  // surface's unit normal at the node (contact: out of the slave surface). A face is coloured when
  // every one of its nodes has a value and its outward normal is within 60 degrees of its nodes'
  // mean normal: the slave faces, not the cut faces or the far faces of a layer whose nodes all
  // lie on the surface. When the model names the slave surfaces' element faces (a deck's
  // *SURFACE; a results file holds none), `support` lists them, (element index, 0-based face),
  // sorted, and only they are coloured (plus, for a slave surface that is a node set,
  // `node_surfaces`, the faces the normal test finds).
  std::vector<Vec3> normals;
  std::vector<std::pair<int, int>> support;
  bool node_surfaces = false;

  bool defined_at(int node) const { return defined.empty() || defined[node] != 0; }
  bool on_surfaces() const { return !normals.empty() || !support.empty() || node_surfaces; }
  // Whether face `face` (0-based) of `element`, whose nodes are `nodes` and whose outward unit
  // normal is `outward`, is coloured.
  bool carries(int element, int face, const std::vector<int>& nodes, const Vec3& outward) const;

  // Stress and strain fields of models with beams or shells: the tensors at every output point of
  // the increment (IncrementResult::S or E, element e's points at point_offset[e] ..) and the
  // function that turns a tensor into the field value. Beams are drawn from these (interpolated
  // over their sections, then evaluated), since averaging at their nodes would lose the bending
  // stress. Empty otherwise. Shells are drawn from them too, on the fibre `shell_fibre`.
  std::vector<int> point_offset;
  std::vector<Tensor6> point_tensors;
  std::function<double(const Tensor6&)> tensor_value;
  ShellFibre shell_fibre = ShellFibre::Top;
  // Section forces and moments (SF.*, SM.*): point_tensors hold one value per station (the
  // increment's station_offset; component in slot 0), not per fibre point. Such a field has a
  // value at the nodes of beams and shells alone (`defined`); other elements show neutral grey.
  bool station_values = false;
};

// Every field name evaluate_field() accepts, for messages and `--help`.
std::vector<std::string> field_names();

// Evaluates field `name` (e.g. "U", "U.z", "RF.mag", "S.mises", "S.p1", "E.11") of `increment`.
// Throws InputError naming the accepted fields when `name` is unknown, and naming the data the
// increment does hold when the requested array is empty (e.g. averaging II asked for, but the
// solver stored no S_nodal_II). Contact fields -- CPRESS (normal pressure), CSHEAR, CSHEAR.1/.2
// (shear traction magnitude / along t1, t2), CSLIP, CSLIP.1/.2 (accumulated slip), CGAP, CSTATUS
// (open / stick / slip) -- are Node fields defined at the slave nodes; an increment without
// contact output is an InputError naming the fields it does hold. A non-empty `contact_pair` (a
// slave surface name) keeps the contact output of that *CONTACT PAIR only.
ScalarField evaluate_field(const Model& model, const IncrementResult& increment,
                           const std::string& name, Averaging averaging,
                           const std::string& contact_pair = "");

// The colour scale of a field over `range` (field_range): a continuous field gets the banded or
// smooth rainbow; a discrete one one band per category with the category colours and names.
ColorScale color_scale_for(const ScalarField& field, const std::array<double, 2>& range, int bands,
                           bool smooth);

// Largest displacement magnitude over the given nodes (all nodes when `nodes` is empty).
double max_displacement(const IncrementResult& increment, const std::vector<int>& nodes);

}  // namespace styk::render
