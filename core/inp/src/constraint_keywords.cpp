// *ORIENTATION and *TRANSFORM (local coordinate systems given by two points) and *EQUATION
// (linear multi-point constraints).
#include <algorithm>

#include "deck_reader.hpp"
#include "numbers.hpp"
#include "styk/core/local_axes.hpp"

namespace styk::inp {

namespace {

CoordinateSystem system_value(const Parameter* p, const SourceLoc& where, const std::string& what) {
  if (!p) return CoordinateSystem::Rectangular;
  const std::string value = normalize_name(p->value);
  if (value == "RECTANGULAR" || value == "R") return CoordinateSystem::Rectangular;
  if (value == "CYLINDRICAL" || value == "C") return CoordinateSystem::Cylindrical;
  throw InputError(where, what + "=" + p->value +
                              " is not supported; expected RECTANGULAR (R) or CYLINDRICAL (C)");
}

// The data line a1, a2, a3, b1, b2, b3, checked to define a system (axes_defect(): the rule
// every module shares).
LocalAxes axes_from(const DataLine& line, CoordinateSystem system) {
  LocalAxes axes;
  axes.system = system;
  const char* names[] = {"a1", "a2", "a3", "b1", "b2", "b3"};
  for (std::size_t i = 0; i < 3; ++i) {
    axes.a[i] = real_field(line, i, std::string("coordinate ") + names[i]);
    axes.b[i] = real_field(line, i + 3, std::string("coordinate ") + names[i + 3]);
  }
  if (const std::string defect = axes_defect(axes); !defect.empty())
    throw InputError(line.where, defect);
  return axes;
}

constexpr const char* kAxesLayout = "a1, a2, a3, b1, b2, b3";

}  // namespace

void DeckReader::on_orientation(const KeywordLine& kw) {
  Orientation orientation;
  orientation.name = normalize_name(kw.find("NAME")->value);
  orientation.where = kw.where;
  if (const auto existing = model_.orientations.find(orientation.name);
      existing != model_.orientations.end())
    throw InputError(kw.where, "orientation " + orientation.name + " is defined twice (first at " +
                                   existing->second.where.str() + ")");
  const CoordinateSystem system = system_value(kw.find("SYSTEM"), kw.where, "SYSTEM");
  // CalculiX's default DEFINITION=COORDINATES is what Styk reads; NODES names the points by node.
  if (const Parameter* definition = kw.find("DEFINITION");
      definition && normalize_name(definition->value) != "COORDINATES")
    throw InputError(kw.where, "DEFINITION=" + definition->value + " of " + kw.label() +
                                   " is not supported; Styk reads DEFINITION=COORDINATES (the "
                                   "default): give the points' coordinates");
  const std::optional<DataLine> line = single_data_line(kw, true, kAxesLayout);
  expect_fields(*line, 6, 6,
                std::string(kAxesLayout) +
                    " (an origin or a second line with an "
                    "extra rotation is not supported)");
  orientation.axes = axes_from(*line, system);
  model_.orientations.emplace(orientation.name, std::move(orientation));
}

void DeckReader::on_transform(const KeywordLine& kw) {
  Transform transform;
  transform.nset = set_name(kw, "NSET");
  transform.where = kw.where;
  const NodeSet* set = model_.find_nset(transform.nset);
  if (!set)
    throw InputError(kw.where,
                     "NSET=" + transform.nset +
                         " of *TRANSFORM is not defined; node sets: " + some_names(model_.nsets));
  // A node has one local system; a second *TRANSFORM reaching it would be ambiguous.
  for (const Transform& other : model_.transforms) {
    const NodeSet* other_set = model_.find_nset(other.nset);
    for (int node : set->nodes)
      if (std::binary_search(other_set->nodes.begin(), other_set->nodes.end(), node))
        throw InputError(kw.where, "node " + std::to_string(model_.node_ids[node]) +
                                       " of NSET=" + transform.nset +
                                       " already has a *TRANSFORM (NSET=" + other.nset + " at " +
                                       other.where.str() + ")");
  }
  const CoordinateSystem system = system_value(kw.find("TYPE"), kw.where, "TYPE");
  const std::optional<DataLine> line = single_data_line(kw, true, kAxesLayout);
  expect_fields(*line, 6, 6, kAxesLayout);
  transform.axes = axes_from(*line, system);
  model_.transforms.push_back(std::move(transform));
}

// One term of an *EQUATION as written: its nodes (one, or a node set's nodes sorted by id), dof
// and coefficient.
struct WrittenTerm {
  std::vector<int> nodes;
  int dof = 1;
  double coefficient = 0.0;
  SourceLoc where;  // its data line
};

void DeckReader::on_equation(const KeywordLine& kw) {
  bool any = false;
  while (std::optional<DataLine> count_line = next_data_line()) {
    expect_fields(*count_line, 1, 1, "the number of terms of the equation, alone on its line");
    const std::int64_t count = integer_field(*count_line, 0, "number of terms");
    if (count < 2)
      throw InputError(count_line->where, "an equation needs at least 2 terms, read " +
                                              count_line->fields[0] +
                                              " (to prescribe a single dof use *BOUNDARY)");
    std::vector<WrittenTerm> terms;
    while (static_cast<std::int64_t>(terms.size()) < count) {
      std::optional<DataLine> line = next_data_line();
      if (!line)
        throw InputError(count_line->where, "the equation announces " + std::to_string(count) +
                                                " terms but gives " + std::to_string(terms.size()));
      const std::size_t n = line->fields.size();
      const std::int64_t missing = count - static_cast<std::int64_t>(terms.size());
      if (n % 3 != 0 || n == 0 || n > 12 || static_cast<std::int64_t>(n / 3) > missing)
        throw InputError(line->where, "*EQUATION term line has " + std::to_string(n) +
                                          " fields, expected node, dof, coefficient for 1 to " +
                                          std::to_string(std::min<std::int64_t>(missing, 4)) +
                                          " terms (" + std::to_string(missing) + " of " +
                                          std::to_string(count) + " terms still to come)");
      for (std::size_t f = 0; f < n; f += 3) {
        const std::string term = "term " + std::to_string(terms.size() + 1);
        WrittenTerm t;
        // A node set (Abaqus) applies the equation to each of its nodes, in ascending id.
        t.nodes = nodes_of(*line, f, "node or node set of " + term);
        std::sort(t.nodes.begin(), t.nodes.end(),
                  [&](int a, int b) { return model_.node_ids[a] < model_.node_ids[b]; });
        t.dof = displacement_dof(*line, f + 1, "dof of " + term);
        t.coefficient = real_field(*line, f + 2, "coefficient of " + term);
        t.where = line->where;
        if (terms.empty() && t.coefficient == 0.0)
          throw InputError(line->where,
                           "the first coefficient of an equation must not be zero: "
                           "the first term is the dof the equation eliminates");
        terms.push_back(std::move(t));
      }
    }
    // Sets of one node repeat their node; all larger sets must be equally long.
    std::size_t copies = 1;
    for (const WrittenTerm& t : terms) {
      if (t.nodes.empty())
        throw InputError(count_line->where, "*EQUATION: a node set of the equation is empty");
      if (t.nodes.size() == 1) continue;
      if (copies != 1 && t.nodes.size() != copies)
        throw InputError(count_line->where,
                         "*EQUATION: its node sets hold " + std::to_string(copies) + " and " +
                             std::to_string(t.nodes.size()) +
                             " nodes; the sets of one equation must be equally long (or hold "
                             "one node, which every copy uses)");
      copies = t.nodes.size();
    }
    for (std::size_t c = 0; c < copies; ++c) add_equation(terms, c, count_line->where);
    any = true;
  }
  if (!any)
    throw InputError(kw.where, kw.label() +
                                   " needs data lines: the number of terms, then node, "
                                   "dof, coefficient for each term");
}

void DeckReader::add_equation(const std::vector<WrittenTerm>& terms, std::size_t copy,
                              const SourceLoc& where) {
  Equation equation;
  equation.where = where;
  for (const WrittenTerm& written : terms) {
    EquationTerm t;
    t.node = written.nodes.size() == 1 ? written.nodes.front() : written.nodes[copy];
    t.dof = written.dof;
    t.coefficient = written.coefficient;
    for (const EquationTerm& other : equation.terms)
      if (other.node == t.node && other.dof == t.dof)
        throw InputError(written.where, "node " + std::to_string(model_.node_ids[t.node]) +
                                            ", dof " + std::to_string(t.dof) +
                                            " appears twice in the equation");
    equation.terms.push_back(t);
  }
  const EquationTerm& dependent = equation.terms.front();
  for (const Equation& other : model_.equations) {
    const EquationTerm& d = other.terms.front();
    if (d.node == dependent.node && d.dof == dependent.dof)
      throw InputError(equation.where,
                       "node " + std::to_string(model_.node_ids[d.node]) + ", dof " +
                           std::to_string(d.dof) +
                           " is already the dependent (first) term of the equation at " +
                           other.where.str() + "; each dof can be eliminated once");
  }
  model_.equations.push_back(std::move(equation));
}

}  // namespace styk::inp
