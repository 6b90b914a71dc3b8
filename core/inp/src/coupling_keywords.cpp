// *COUPLING with *KINEMATIC or *DISTRIBUTING, *MPC (BEAM, STRAIGHT, PLANE) and *PRE-TENSION
// SECTION: constraints that the solver turns into linear equations (or, for *DISTRIBUTING,
// into a distribution of the reference node's loads). Surfaces may be defined after the
// keyword; resolve_constraint_references() checks them once the deck is complete.
#include <algorithm>
#include <cmath>

#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {

namespace {

// The single node a parameter names: a node id or a set holding exactly one node.
int single_node(const Model& model, const KeywordLine& kw, const char* param) {
  const Parameter* p = kw.find(param);
  const std::string text = p->value;
  if (!names_a_set(text)) {
    const std::int64_t id = integer_value(text, std::string(param) + "=", kw.where);
    const int index = model.node_index(id);
    if (index < 0)
      throw InputError(kw.where, std::string(param) + "=" + text + ": node " + text +
                                     " is not defined (define it with *NODE above)");
    return index;
  }
  const NodeSet* set = model.find_nset(text);
  if (!set || set->nodes.size() != 1)
    throw InputError(kw.where, std::string(param) + "=" + text +
                                   ": expected a node id or a node set holding one node");
  return set->nodes.front();
}

// Data lines "first dof[, last dof]" into a sorted list of dofs within [1, max_dof].
std::vector<int> dof_ranges(const std::vector<DataLine>& lines, int max_dof,
                            const std::string& keyword) {
  std::vector<int> dofs;
  for (const DataLine& line : lines) {
    if (line.fields.empty() || line.fields.size() > 2)
      throw InputError(line.where, keyword + " data line: first dof[, last dof]");
    const std::int64_t first = integer_field(line, 0, "first dof");
    const std::int64_t last = line.fields.size() > 1 && !line.fields[1].empty()
                                  ? integer_field(line, 1, "last dof")
                                  : first;
    if (first < 1 || last > max_dof || last < first)
      throw InputError(line.where, keyword + ": dofs " + std::to_string(first) + " to " +
                                       std::to_string(last) + " are out of range 1.." +
                                       std::to_string(max_dof));
    for (std::int64_t d = first; d <= last; ++d) dofs.push_back(static_cast<int>(d));
  }
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

}  // namespace

void DeckReader::on_coupling(const KeywordLine& kw) {
  Coupling coupling;
  coupling.name = normalize_name(kw.find("CONSTRAINT NAME")->value);
  coupling.reference_node = single_node(model_, kw, "REF NODE");
  coupling.surface = normalize_name(kw.find("SURFACE")->value);
  if (const Parameter* orientation = kw.find("ORIENTATION"))
    coupling.orientation = normalize_name(orientation->value);
  coupling.where = kw.where;
  for (const Coupling& other : model_.couplings)
    if (other.name == coupling.name)
      throw InputError(kw.where, "*COUPLING, CONSTRAINT NAME=" + coupling.name +
                                     " is defined twice (first at " + other.where.str() + ")");
  model_.couplings.push_back(std::move(coupling));
  coupling_open_ = true;  // *KINEMATIC or *DISTRIBUTING must follow
}

void DeckReader::on_coupling_kind(const KeywordLine& kw) {
  if (!coupling_open_)
    throw InputError(kw.where, kw.label() + " must follow a *COUPLING line directly");
  coupling_open_ = false;
  Coupling& coupling = model_.couplings.back();
  const bool kinematic = kw.name == "KINEMATIC";
  coupling.kind = kinematic ? Coupling::Kind::Kinematic : Coupling::Kind::Distributing;
  coupling.kind_where = kw.where;
  std::vector<DataLine> lines;
  while (std::optional<DataLine> line = next_data_line()) lines.push_back(std::move(*line));
  if (kinematic) {
    // CalculiX: the translations 1..3 follow the reference node rigidly (its rotation about it
    // included); at least one line.
    if (lines.empty())
      throw InputError(kw.where, "*KINEMATIC needs data lines: first dof[, last dof] (1..3)");
    coupling.dofs = dof_ranges(lines, 3, "*KINEMATIC");
  } else {
    // CalculiX: the forces (1..3) are always distributed; listed rotations 4..6 add the moments.
    coupling.dofs = dof_ranges(lines, 6, "*DISTRIBUTING");
  }
}

void DeckReader::on_mpc(const KeywordLine& kw) {
  bool any = false;
  std::optional<DataLine> line = next_data_line();
  while (line) {
    Mpc mpc;
    mpc.where = line->where;
    const std::string type = line->fields.empty() ? "" : normalize_name(line->fields[0]);
    if (type == "BEAM")
      mpc.type = Mpc::Type::Beam;
    else if (type == "STRAIGHT")
      mpc.type = Mpc::Type::Straight;
    else if (type == "PLANE")
      mpc.type = Mpc::Type::Plane;
    else
      throw InputError(line->where, "*MPC type " +
                                        quote(line->fields.empty() ? "" : line->fields[0]) +
                                        " is not supported; Styk reads BEAM, STRAIGHT and PLANE "
                                        "(user MPCs need a subroutine)");
    // The nodes: the rest of this line and following lines up to the next type name; zero
    // entries are discarded (CalculiX).
    auto take_nodes = [&](const DataLine& from, std::size_t first) {
      for (std::size_t i = first; i < from.fields.size(); ++i) {
        if (from.fields[i].empty()) continue;
        const Id id = integer_field(from, i, "node of the MPC");
        if (id == 0) continue;
        mpc.nodes.push_back(node_by_id(id, from.where, "*MPC " + type));
      }
    };
    take_nodes(*line, 1);
    line = next_data_line();
    while (line && !line->fields.empty() && !names_a_set(line->fields[0])) {
      take_nodes(*line, 0);
      line = next_data_line();
    }
    const std::size_t needed = mpc.type == Mpc::Type::Beam       ? 2
                               : mpc.type == Mpc::Type::Straight ? 3
                                                                 : 4;
    if (mpc.nodes.size() < needed || (mpc.type == Mpc::Type::Beam && mpc.nodes.size() != 2))
      throw InputError(mpc.where,
                       "*MPC " + type + " needs " +
                           (mpc.type == Mpc::Type::Beam ? std::string("exactly 2")
                                                        : "at least " + std::to_string(needed)) +
                           " nodes, the line gives " + std::to_string(mpc.nodes.size()));
    for (std::size_t i = 0; i < mpc.nodes.size(); ++i)
      for (std::size_t j = i + 1; j < mpc.nodes.size(); ++j)
        if (mpc.nodes[i] == mpc.nodes[j])
          throw InputError(mpc.where, "*MPC " + type + ": node " +
                                          std::to_string(model_.node_ids[mpc.nodes[i]]) +
                                          " is listed twice");
    model_.mpcs.push_back(std::move(mpc));
    any = true;
  }
  if (!any) throw InputError(kw.where, "*MPC needs data lines: type, node, node, ...");
}

void DeckReader::on_pretension_section(const KeywordLine& kw) {
  if (kw.find("ELEMENT"))
    throw InputError(kw.where,
                     "*PRE-TENSION SECTION, ELEMENT= (a beam bolt) is not supported; "
                     "give SURFACE= (a cross-section of a solid bolt)");
  if (!kw.find("SURFACE"))
    throw InputError(kw.where,
                     "*PRE-TENSION SECTION needs SURFACE= (the element faces of a "
                     "cross-section of the bolt)");
  PretensionSection section;
  section.surface = normalize_name(kw.find("SURFACE")->value);
  section.reference_node = single_node(model_, kw, "NODE");
  section.where = kw.where;
  for (const PretensionSection& other : model_.pretension_sections)
    if (other.reference_node == section.reference_node)
      throw InputError(kw.where, "NODE=" + kw.find("NODE")->value +
                                     " is already the reference node of the pre-tension section "
                                     "at " +
                                     other.where.str());
  if (const std::optional<DataLine> line = single_data_line(kw, false, "normal x, y, z")) {
    expect_fields(*line, 3, 3, "normal x, y, z");
    Vec3 n{};
    for (std::size_t i = 0; i < 3; ++i)
      n[i] = real_field(*line, i, "normal component " + std::to_string(i + 1));
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0.0)) throw InputError(line->where, "the pre-tension normal is the zero vector");
    for (double& c : n) c /= length;
    section.normal = n;
  }
  model_.pretension_sections.push_back(std::move(section));
}

int DeckReader::load_dof(const DataLine& line) const {
  const std::int64_t dof = integer_field(line, 1, "dof");
  if (dof < 4 || dof > 6) return displacement_dof(line, 1, "dof");
  // A moment: taken by beam nodes (the solver names a node without rotations) and by the
  // reference node of a distributing coupling, which carries it to its surface.
  return static_cast<int>(dof);
}

void DeckReader::resolve_constraint_references() {
  auto surface = [&](const std::string& name, const SourceLoc& where, const std::string& what,
                     bool faces_only) -> const Surface& {
    const auto it = model_.surfaces.find(name);
    if (it == model_.surfaces.end())
      throw InputError(where,
                       what + " names surface " + name +
                           ", which is not defined; surfaces: " + some_names(model_.surfaces));
    if (faces_only && it->second.kind != Surface::Kind::ElementFaces)
      throw InputError(where, what + ": surface " + name +
                                  " is a node surface; it must consist of element faces");
    return it->second;
  };
  for (const Tie& tie : model_.ties) {
    surface(tie.slave, tie.where, "*TIE " + tie.name + " (slave)", false);
    surface(tie.master, tie.where, "*TIE " + tie.name + " (master)", true);
  }
  for (const Coupling& coupling : model_.couplings) {
    if (coupling.kind_where.line == 0 && coupling.kind_where.file.empty())
      throw InputError(coupling.where, "*COUPLING " + coupling.name +
                                           " needs *KINEMATIC or *DISTRIBUTING right after it");
    surface(coupling.surface, coupling.where, "*COUPLING " + coupling.name,
            coupling.kind == Coupling::Kind::Distributing);
    if (!coupling.orientation.empty() && model_.orientations.count(coupling.orientation) == 0)
      throw InputError(coupling.where, "*COUPLING " + coupling.name + ": ORIENTATION=" +
                                           coupling.orientation + " is not defined");
  }
  for (const PretensionSection& section : model_.pretension_sections)
    surface(section.surface, section.where, "*PRE-TENSION SECTION", true);
}

}  // namespace styk::inp
