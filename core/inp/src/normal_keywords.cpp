// *NORMAL (CalculiX/Abaqus, TYPE=ELEMENT): data lines "element or element set, node or node set,
// nx, ny, nz" give the normal of a shell at a node, replacing the normal Styk would average
// there (a fold line, or the exact normal on a symmetry edge). TYPE=CONTACT SURFACE and normals
// of beams (their second section axis comes from *BEAM SECTION) are refused by name.
#include <algorithm>
#include <cmath>

#include "deck_reader.hpp"
#include "numbers.hpp"
#include "styk/core/shell_normals.hpp"

namespace styk::inp {
namespace {

// The shell elements of the degenerated (curved) kind are the ones whose nodes carry normals;
// the Kirchhoff triangle STRI3 is flat and takes its plane's normal.
void check_takes_normals(const Element& element, const TElement* formulation,
                         const SourceLoc& where) {
  const std::string name = "element " + std::to_string(element.id) + " (" + element.type + ")";
  if (!formulation || formulation->section_measure() != SectionMeasure::Shell)
    throw InputError(where, "*NORMAL on " + name +
                                ": Styk takes nodal normals for shell elements only (a beam's "
                                "second section axis is given on its *BEAM SECTION)");
  if (formulation->node_count() == 3)
    throw InputError(where, "*NORMAL on " + name +
                                ": the flat Kirchhoff triangle takes the normal of its plane");
}

Vec3 normal_direction(const DataLine& line) {
  const Vec3 n{real_field(line, 2, "nx"), real_field(line, 3, "ny"), real_field(line, 4, "nz")};
  if (!(std::hypot(n[0], n[1], n[2]) > 0.0))
    throw InputError(line.where, "*NORMAL: the normal (fields 3-5) must not be zero");
  return n;
}

}  // namespace

void DeckReader::on_normal(const KeywordLine& kw) {
  if (const Parameter* type = kw.find("TYPE"); type && normalize_name(type->value) != "ELEMENT")
    throw InputError(kw.where, "*NORMAL, TYPE=" + type->value +
                                   " is not supported (Styk reads TYPE=ELEMENT: nodal normals "
                                   "of shell elements)");
  bool any = false;
  while (const std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 5, 5, "element or element set, node or node set, nx, ny, nz");
    const std::vector<int> elements = elements_of(*line, 0, "element or element set");
    const std::vector<int> nodes = nodes_of(*line, 1, "node or node set");
    const Vec3 direction = normal_direction(*line);
    int given = 0;
    for (const int e : elements) {
      const Element& element = model_.elements[e];
      check_takes_normals(element, registry_.find(element.type), line->where);
      const int* first = model_.element_nodes(e);
      const int* last = first + element.node_count;
      for (const int node : nodes) {
        if (std::find(first, last, node) == last) continue;
        model_.normals.push_back({e, node, direction, line->where});
        ++given;
      }
    }
    if (given == 0)
      throw InputError(line->where, "*NORMAL: " + line->fields[1] + " (field 2) names no node of " +
                                        line->fields[0] + " (field 1)");
    any = true;
  }
  if (!any)
    throw InputError(kw.where,
                     "*NORMAL needs data lines: element or element set, node or node set, nx, "
                     "ny, nz");
}

void DeckReader::resolve_node_normals() {
  if (node_normals_.empty()) return;
  // Which shells take normals at each node.
  std::vector<std::vector<int>> shells_at(model_.coords.size());
  for (int e = 0; e < model_.element_count(); ++e) {
    const TElement* formulation = registry_.find(model_.elements[e].type);
    if (!formulation || !takes_nodal_normals(*formulation)) continue;
    const int* nodes = model_.element_nodes(e);
    for (int k = 0; k < model_.elements[e].node_count; ++k) shells_at[nodes[k]].push_back(e);
  }
  std::vector<UserNormal> given;
  for (const NodeNormal& n : node_normals_) {
    if (shells_at[n.node].empty())
      throw InputError(n.where, "*NODE: node " + std::to_string(model_.node_ids[n.node]) +
                                    " has a normal (fields 5-7) but belongs to no curved shell "
                                    "element; Styk takes nodal normals for shells only (a "
                                    "beam's second section axis is given on its *BEAM SECTION)");
    for (const int e : shells_at[n.node]) given.push_back({e, n.node, n.direction, n.where});
  }
  // The deck's *NORMAL lines come later, so they win for their element and node.
  model_.normals.insert(model_.normals.begin(), given.begin(), given.end());
}

}  // namespace styk::inp
