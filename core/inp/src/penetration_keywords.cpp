// *PRESSURE PENETRATION (after Abaqus/Standard; a Styk extension for CalculiX, which has no such
// keyword): a fluid pressure entering a contact interface at exposed nodes (docs/input.md). Step
// data; the contact pair and its surfaces are checked once the deck is complete
// (resolve_penetration_references), since surfaces may be defined after the pair.
#include <algorithm>

#include "deck_reader.hpp"
#include "numbers.hpp"
#include "writer_parts.hpp"

namespace styk::inp {

namespace {

bool op_is_new(const KeywordLine& kw) {
  const Parameter* op = kw.find("OP");
  if (!op) return false;
  const std::string value = normalize_name(op->value);
  if (value != "NEW" && value != "MOD")
    throw InputError(kw.where, "OP=" + op->value + " on " + kw.label() + ": expected NEW or MOD");
  return value == "NEW";
}

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// The nodes of a surface: its node list, or the nodes of its element faces.
std::vector<int> surface_nodes(const Model& model, const ElementRegistry& registry,
                               const Surface& surface) {
  std::vector<int> nodes = surface.nodes;
  for (const SurfaceFace& f : surface.faces) {
    const Element& element = model.elements[f.element];
    const TElement* formulation = registry.find(element.type);
    if (!formulation) continue;  // the element's own check names an unknown type
    const int* element_nodes = model.element_nodes(f.element);
    for (int local : formulation->faces()[f.face - 1].nodes) nodes.push_back(element_nodes[local]);
  }
  sort_unique(nodes);
  return nodes;
}

// The first of `nodes` that is not in the sorted `allowed`, or -1.
int first_outside(const std::vector<int>& nodes, const std::vector<int>& allowed) {
  for (int node : nodes)
    if (!std::binary_search(allowed.begin(), allowed.end(), node)) return node;
  return -1;
}

constexpr const char* kLayout =
    "exposed slave node or node set, exposed master node or node set, fluid pressure[, critical "
    "contact pressure]";

}  // namespace

void DeckReader::on_pressure_penetration(const KeywordLine& kw) {
  Step& step = current_step();
  if (op_is_new(kw)) {
    step.penetration_op_new = true;
    step.penetrations.clear();
  }
  PressurePenetration pp;
  pp.slave = set_name(kw, "SLAVE");
  pp.master = set_name(kw, "MASTER");
  if (kw.find("LEAK")) pp.leak_nset = set_name(kw, "LEAK");
  pp.where = kw.where;
  bool first = true;
  while (std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 3, 4, kLayout);
    const std::vector<int> slave = nodes_of(*line, 0, "exposed slave node or node set");
    const std::vector<int> master = nodes_of(*line, 1, "exposed master node or node set");
    const double pressure = real_field(*line, 2, "fluid pressure");
    const double critical = line->fields.size() > 3 && !line->fields[3].empty()
                                ? real_field(*line, 3, "critical contact pressure")
                                : 0.0;
    if (critical < 0.0)
      throw InputError(line->where, "the critical contact pressure must not be negative, read " +
                                        line->fields[3]);
    if (!first && (pressure != pp.pressure || critical != pp.critical))
      throw InputError(line->where,
                       "every data line of one *PRESSURE PENETRATION must give the same fluid and "
                       "critical pressures (different magnitudes per entry point are not "
                       "supported); read " +
                           line->fields[2] + " after " + shortest_number(pp.pressure));
    pp.pressure = pressure;
    pp.critical = critical;
    pp.exposed_slave.insert(pp.exposed_slave.end(), slave.begin(), slave.end());
    pp.exposed_master.insert(pp.exposed_master.end(), master.begin(), master.end());
    first = false;
  }
  if (first) throw InputError(kw.where, kw.label() + " needs a data line: " + kLayout);
  sort_unique(pp.exposed_slave);
  sort_unique(pp.exposed_master);
  // A later definition for the same pair replaces the earlier one (OP=MOD).
  step.penetrations.erase(std::remove_if(step.penetrations.begin(), step.penetrations.end(),
                                         [&](const PressurePenetration& other) {
                                           return other.slave == pp.slave &&
                                                  other.master == pp.master;
                                         }),
                          step.penetrations.end());
  step.penetrations.push_back(std::move(pp));
}

void DeckReader::resolve_penetration_references() {
  for (const Step& step : model_.steps)
    for (const PressurePenetration& pp : step.penetrations) {
      const auto pair = std::find_if(
          model_.contact_pairs.begin(), model_.contact_pairs.end(),
          [&](const ContactPair& p) { return p.slave == pp.slave && p.master == pp.master; });
      if (pair == model_.contact_pairs.end())
        throw InputError(pp.where, "*PRESSURE PENETRATION: no *CONTACT PAIR has slave " + pp.slave +
                                       " and master " + pp.master);
      const std::vector<int> slave = surface_nodes(model_, registry_, model_.surfaces.at(pp.slave));
      const std::vector<int> master =
          surface_nodes(model_, registry_, model_.surfaces.at(pp.master));
      if (const int node = first_outside(pp.exposed_slave, slave); node >= 0)
        throw InputError(pp.where, "*PRESSURE PENETRATION: exposed node " +
                                       std::to_string(model_.node_ids[node]) +
                                       " is not a node of the slave surface " + pp.slave);
      if (const int node = first_outside(pp.exposed_master, master); node >= 0)
        throw InputError(pp.where, "*PRESSURE PENETRATION: exposed node " +
                                       std::to_string(model_.node_ids[node]) +
                                       " is not a node of the master surface " + pp.master);
      if (pp.leak_nset.empty()) continue;
      const NodeSet* leak = model_.find_nset(pp.leak_nset);
      if (!leak)
        throw InputError(pp.where, "LEAK=" + pp.leak_nset +
                                       " is not defined; node sets: " + some_names(model_.nsets));
      if (const int node = first_outside(leak->nodes, slave); node >= 0)
        throw InputError(pp.where, "LEAK=" + pp.leak_nset + ": node " +
                                       std::to_string(model_.node_ids[node]) +
                                       " is not a node of the slave surface " + pp.slave);
    }
}

}  // namespace styk::inp
