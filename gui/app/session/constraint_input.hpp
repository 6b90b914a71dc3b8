// Constraints and sets as the dialogs ask for them: *EQUATION (terms node id, dof, coefficient),
// *TRANSFORM of a node set (rectangular or cylindrical), and a node set made of the nodes two
// sets share (e.g. the line where a revolve's inner cylinder meets its cut plane, for a chart).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "session/commands.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

struct EquationTermInput {
  Id node = 0;  // node id, as in the deck
  int dof = 1;
  double coefficient = 0.0;
};
// Lines "node, dof, coefficient" (commas or spaces); InputError naming the line otherwise.
std::vector<EquationTermInput> parse_equation_terms(const std::string& text);
// Refused: fewer than 2 terms, an unknown node, dof outside 1..3, a first coefficient of 0, a
// node/dof twice, a first term that another equation eliminates or a *BOUNDARY prescribes.
std::unique_ptr<Command> equation_command(const Model& model,
                                          const std::vector<EquationTermInput>& terms);

struct TransformInput {
  std::string nset;
  bool cylindrical = false;
  Vec3 a{1, 0, 0};  // rectangular: local x along a, y in the plane of a and b;
  Vec3 b{0, 1, 0};  // cylindrical: two points of the axis (1 radial, 2 tangential, 3 axial)
};
// Refused: unknown set, degenerate axes, a node that has a transform already or (cylindrical)
// lies on the axis.
std::unique_ptr<Command> transform_command(const Model& model, const TransformInput& input);

// Editing: the checks above, except against the equation / transform being replaced (index).
// equation_text() gives the dialog's text ("node dof coefficient; ...", node ids).
Equation checked_equation(const Model& model, const std::vector<EquationTermInput>& terms,
                          int replacing);
Transform checked_transform(const Model& model, const TransformInput& input, int replacing);
std::string equation_text(const Model& model, int equation);
TransformInput transform_input_of(const Model& model, int transform);
std::unique_ptr<Command> equation_edit_command(const Model& model, int equation,
                                               const std::vector<EquationTermInput>& terms);
std::unique_ptr<Command> transform_edit_command(const Model& model, int transform,
                                                const TransformInput& input);

struct CommonNodesInput {
  std::string name;
  std::string first;
  std::string second;
};
std::unique_ptr<Command> common_nodes_command(const Model& model, const CommonNodesInput& input);

}  // namespace styk::gui
