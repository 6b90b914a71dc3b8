#include "session/constraint_input.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <sstream>

#include "session/input_checks.hpp"
#include "session/orientation_input.hpp"
#include "session/validation.hpp"
#include "styk/core/local_axes.hpp"

namespace styk::gui {
namespace {

bool prescribed(const Model& model, int node, int dof) {
  const auto hits = [&](const std::vector<Boundary>& list) {
    return std::any_of(list.begin(), list.end(),
                       [&](const Boundary& b) { return b.node == node && b.dof == dof; });
  };
  if (hits(model.boundaries)) return true;
  return std::any_of(model.steps.begin(), model.steps.end(),
                     [&](const Step& s) { return hits(s.boundaries); });
}

}  // namespace

std::vector<EquationTermInput> parse_equation_terms(const std::string& text) {
  std::vector<EquationTermInput> terms;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    std::vector<std::string> f{std::istream_iterator<std::string>(fields), {}};
    if (f.empty()) continue;
    const std::string where = "term line " + std::to_string(number);
    if (f.size() != 3) refuse(where + ": give node, dof, coefficient");
    terms.push_back({parse_integer(f[0], where + " node"), parse_integer(f[1], where + " dof"),
                     parse_real(f[2], where + " coefficient")});
  }
  return terms;
}

Equation checked_equation(const Model& model, const std::vector<EquationTermInput>& terms,
                          int replacing) {
  if (terms.size() < 2)
    refuse("an equation needs at least 2 terms (one term is a boundary condition)");
  Equation eq;
  std::set<std::pair<int, int>> seen;
  for (const EquationTermInput& t : terms) {
    const int node = model.node_index(t.node);
    if (node < 0) refuse("no node " + std::to_string(t.node) + " in the model");
    check_dof(t.dof, "dof");
    check_finite(t.coefficient, "coefficient");
    if (!seen.insert({node, t.dof}).second)
      refuse("node " + std::to_string(t.node) + " dof " + std::to_string(t.dof) +
             " appears twice in the equation");
    eq.terms.push_back({node, t.dof, t.coefficient});
  }
  const EquationTerm& first = eq.terms.front();
  const std::string dependent =
      "node " + std::to_string(terms.front().node) + " dof " + std::to_string(first.dof);
  if (first.coefficient == 0.0)
    refuse("the first term's coefficient must not be 0 (it is the dof the equation eliminates)");
  for (int i = 0; i < static_cast<int>(model.equations.size()); ++i) {
    const Equation& other = model.equations[i];
    if (i != replacing && other.terms.front().node == first.node &&
        other.terms.front().dof == first.dof)
      refuse(dependent + " is eliminated by another equation already");
  }
  if (prescribed(model, first.node, first.dof))
    refuse(dependent + " is prescribed by a boundary condition; it cannot be the first term");
  return eq;
}

std::unique_ptr<Command> equation_command(const Model& model,
                                          const std::vector<EquationTermInput>& terms) {
  const Equation eq = checked_equation(model, terms, -1);
  const std::string dependent =
      "node " + std::to_string(terms.front().node) + " dof " + std::to_string(eq.terms.front().dof);
  return make_model_edit(
      "Add equation on " + dependent, [eq](Model& m) { m.equations.push_back(eq); },
      [](Model& m) { m.equations.pop_back(); });
}

Transform checked_transform(const Model& model, const TransformInput& in, int replacing) {
  const NodeSet& set = existing_nset(model, in.nset);
  const LocalAxes axes = local_axes(in.cylindrical, in.a, in.b);  // shared with *ORIENTATION
  for (int n : set.nodes)
    if (const std::string defect = axes_defect_at(axes, model.coords[n]); !defect.empty())
      refuse("node " + std::to_string(model.node_ids[n]) + " " + defect);
  for (int i = 0; i < static_cast<int>(model.transforms.size()); ++i) {
    if (i == replacing) continue;
    const Transform& t = model.transforms[i];
    const NodeSet* other = model.find_nset(t.nset);
    if (!other) continue;
    for (int n : set.nodes)
      if (std::binary_search(other->nodes.begin(), other->nodes.end(), n))
        refuse("node " + std::to_string(model.node_ids[n]) + " has a transform already (set " +
               t.nset + "); a node may have one");
  }
  Transform t;
  t.nset = set.name;
  t.axes = axes;
  return t;
}

std::unique_ptr<Command> transform_command(const Model& model, const TransformInput& in) {
  const Transform t = checked_transform(model, in, -1);
  return make_model_edit(
      std::string("Add ") + (in.cylindrical ? "cylindrical" : "rectangular") + " transform on " +
          t.nset,
      [t](Model& m) { m.transforms.push_back(t); }, [](Model& m) { m.transforms.pop_back(); });
}

std::string equation_text(const Model& model, int equation) {
  if (equation < 0 || equation >= static_cast<int>(model.equations.size()))
    refuse("no equation " + std::to_string(equation + 1) + " in the model");
  std::ostringstream text;
  for (const EquationTerm& t : model.equations[equation].terms)
    text << (text.tellp() > 0 ? "; " : "") << model.node_ids[t.node] << " " << t.dof << " "
         << t.coefficient;
  return text.str();
}

TransformInput transform_input_of(const Model& model, int transform) {
  if (transform < 0 || transform >= static_cast<int>(model.transforms.size()))
    refuse("no transform " + std::to_string(transform + 1) + " in the model");
  const Transform& t = model.transforms[transform];
  return {t.nset, t.axes.system == CoordinateSystem::Cylindrical, t.axes.a, t.axes.b};
}

std::unique_ptr<Command> equation_edit_command(const Model& model, int equation,
                                               const std::vector<EquationTermInput>& terms) {
  equation_text(model, equation);  // checks the index
  const Equation after = checked_equation(model, terms, equation);
  const Equation before = model.equations[equation];
  return make_model_edit(
      "Edit equation " + std::to_string(equation + 1),
      [equation, after](Model& m) { m.equations[equation] = after; },
      [equation, before](Model& m) { m.equations[equation] = before; });
}

std::unique_ptr<Command> transform_edit_command(const Model& model, int transform,
                                                const TransformInput& input) {
  transform_input_of(model, transform);  // checks the index
  const Transform after = checked_transform(model, input, transform);
  const Transform before = model.transforms[transform];
  return make_model_edit(
      "Edit transform on " + before.nset,
      [transform, after](Model& m) { m.transforms[transform] = after; },
      [transform, before](Model& m) { m.transforms[transform] = before; });
}

std::unique_ptr<Command> common_nodes_command(const Model& model, const CommonNodesInput& in) {
  check_name(in.name, "the node set");
  const std::string name = to_upper(in.name);
  if (model.find_nset(name)) refuse("node set " + name + " exists already");
  const NodeSet& a = existing_nset(model, in.first);
  const NodeSet& b = existing_nset(model, in.second);
  NodeSet set;
  set.name = name;
  std::set_intersection(a.nodes.begin(), a.nodes.end(), b.nodes.begin(), b.nodes.end(),
                        std::back_inserter(set.nodes));
  if (set.nodes.empty()) refuse("node sets " + a.name + " and " + b.name + " share no node");
  return make_add_node_set(std::move(set));
}

}  // namespace styk::gui
