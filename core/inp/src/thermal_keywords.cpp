// *INITIAL CONDITIONS, TYPE=TEMPERATURE (model) and *TEMPERATURE (step): nodal temperatures that
// drive the thermal strain of materials with *EXPANSION.
#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {

namespace {

// Lines "node or node set, temperature" appended to `target`, one entry per node.
template <class NodesOf>
void read_temperatures(const DataLine& line, NodesOf&& nodes_of,
                       std::vector<NodalTemperature>& target) {
  const double value = real_field(line, 1, "temperature");
  for (int node : nodes_of(line)) target.push_back({node, value, line.where});
}

}  // namespace

void DeckReader::on_initial_conditions(const KeywordLine& kw) {
  const Parameter* type = kw.find("TYPE");
  if (normalize_name(type->value) == "STRESS") {
    read_initial_stresses(kw);  // load_keywords.cpp
    return;
  }
  if (normalize_name(type->value) != "TEMPERATURE")
    throw InputError(kw.where, "*INITIAL CONDITIONS, TYPE=" + type->value +
                                   " is not supported; Styk reads TYPE=TEMPERATURE and "
                                   "TYPE=STRESS");
  if (kw.find("USER"))
    throw InputError(kw.where,
                     "*INITIAL CONDITIONS, USER needs a user subroutine, which Styk "
                     "does not run");
  bool any = false;
  while (std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 2, 2, "node or node set, temperature");
    read_temperatures(
        *line, [&](const DataLine& l) { return nodes_of(l, 0, "node or node set"); },
        model_.initial_temperatures);
    any = true;
  }
  if (!any)
    throw InputError(kw.where, kw.label() + " needs data lines: node or node set, temperature");
}

void DeckReader::on_temperature(const KeywordLine& kw) {
  Step& step = current_step();
  if (const Parameter* op = kw.find("OP")) {
    const std::string value = normalize_name(op->value);
    if (value == "NEW")
      step.temperature_op_new = true;
    else if (value != "MOD")
      throw InputError(kw.where, "OP=" + op->value + " on *TEMPERATURE: expected NEW or MOD");
  }
  bool any = false;
  while (std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 2, 2, "node or node set, temperature");
    read_temperatures(
        *line, [&](const DataLine& l) { return nodes_of(l, 0, "node or node set"); },
        step.temperatures);
    any = true;
  }
  if (!any && !step.temperature_op_new)
    throw InputError(kw.where, kw.label() +
                                   " needs data lines: node or node set, temperature "
                                   "(or OP=NEW to return to the initial temperatures)");
}

}  // namespace styk::inp
