// Steady scalar fields (docs/input.md, "Steady heat and electric potential"): the procedures
// *HEAT TRANSFER, STEADY STATE and *COUPLED THERMAL-ELECTRICAL, STEADY STATE (Styk solves its
// electric part only), the materials' *CONDUCTIVITY and *ELECTRICAL CONDUCTIVITY, the loads
// *CFLUX, *CECUR and *DFLUX, and the checks that keep scalar and mechanical data apart.
#include <algorithm>

#include "deck_reader.hpp"
#include "numbers.hpp"
#include "styk/core/step_kind.hpp"

namespace styk::inp {

namespace {

// OP=NEW|MOD inside a step; true for NEW.
bool op_new(const KeywordLine& kw) {
  const Parameter* op = kw.find("OP");
  if (!op) return false;
  const std::string value = normalize_name(op->value);
  if (value != "NEW" && value != "MOD")
    throw InputError(kw.where, "OP=" + op->value + " on " + kw.label() + ": expected NEW or MOD");
  return value == "NEW";
}

std::string dof_name(int dof) {
  if (dof == 11) return "dof 11 (temperature)";
  if (dof == 9) return "dof 9 (electric potential)";
  return "dof " + std::to_string(dof) + (dof > 3 ? " (rotation)" : " (displacement)");
}

// Whether `dof` belongs to a step of `kind`.
bool dof_fits(int dof, StepKind kind) {
  const int scalar = scalar_dof(kind);
  return scalar == 0 ? dof >= 1 && dof <= 6 : dof == scalar;
}

std::string what_step_takes(StepKind kind) {
  const int scalar = scalar_dof(kind);
  return scalar == 0
             ? std::string("mechanical steps take dofs 1..6")
             : std::string(procedure_keyword(kind)) + " steps take " + dof_name(scalar) + " only";
}

// The output variables of *NODE PRINT / *EL PRINT / *NODE FILE / *EL FILE per step kind
// (*CONTACT PRINT's own variables belong to mechanical steps).
const std::vector<std::string>& variables(StepKind kind) {
  static const std::vector<std::string> kStatic = {
      "U",    "RF",   "UR",   "RM",   "S",   "E",   "SF",  "SM",  "CSTR", "CDIS",  "CSTATUS",
      "ENER", "ELSE", "EVOL", "CENT", "THE", "ERR", "NOE", "SOF", "SOM",  "SOAREA"};
  static const std::vector<std::string> kHeat = {"NT", "RFL", "HFL"};
  static const std::vector<std::string> kElectric = {"EPOT", "RECUR", "ECD"};
  return kind == StepKind::HeatTransfer         ? kHeat
         : kind == StepKind::ElectricConduction ? kElectric
                                                : kStatic;
}

bool variable_fits(const std::string& var, StepKind kind) {
  const std::vector<std::string>& list = variables(kind);
  return std::find(list.begin(), list.end(), var) != list.end();
}

std::string variables_of(StepKind kind) {
  std::string out;
  for (const std::string& v : variables(kind)) out += (out.empty() ? "" : ", ") + v;
  return out;
}

// Diagonal conductivity from one data line: k (isotropic) or k11, k22, k33 (orthotropic).
std::array<double, 3> read_conductivity(const DataLine& line, bool orthotropic,
                                        const std::string& what) {
  std::array<double, 3> k{};
  for (int i = 0; i < 3; ++i) {
    const std::size_t field = orthotropic ? static_cast<std::size_t>(i) : 0;
    k[i] = real_field(line, field, orthotropic ? what + " k" + std::to_string(11 * (i + 1)) : what);
    if (!(k[i] > 0.0))
      throw InputError(line.where, what + " must be positive, read " + line.fields[field]);
  }
  return k;
}

}  // namespace

void DeckReader::read_scalar_procedure(const KeywordLine& kw, StepKind kind) {
  Step& step = current_step();
  if (step.has_procedure)
    throw InputError(kw.where, "this step already has a procedure (at " +
                                   step.procedure.where.str() + "); one per step");
  if (!kw.find("STEADY STATE"))
    throw InputError(kw.where, kw.label() +
                                   " without STEADY STATE is a transient analysis, which Styk "
                                   "does not solve; write " +
                                   kw.label() + ", STEADY STATE");
  StaticProcedure proc;
  proc.where = kw.where;
  const std::string layout = "initial increment, step time, minimum increment, maximum increment";
  if (const std::optional<DataLine> line = single_data_line(kw, false, layout)) {
    expect_fields(*line, 0, 4, layout);
    for (std::size_t i = 0; i < line->fields.size(); ++i) {
      if (line->fields[i].empty()) continue;
      const double value = real_field(*line, i, i == 1 ? "step time" : "increment");
      if (!(value > 0.0))
        throw InputError(line->where, "field " + std::to_string(i + 1) +
                                          " must be positive, read " + line->fields[i]);
      if (i == 0) proc.initial_increment = value;
      if (i == 1) proc.total_time = value;
    }
    // A steady state has no history: one increment covers the step whatever the data line says.
    proc.initial_increment = proc.total_time;
  }
  step.kind = kind;
  step.procedure = proc;
  step.has_procedure = true;
}

void DeckReader::on_heat_transfer(const KeywordLine& kw) {
  read_scalar_procedure(kw, StepKind::HeatTransfer);
}

void DeckReader::on_coupled_thermal_electrical(const KeywordLine& kw) {
  read_scalar_procedure(kw, StepKind::ElectricConduction);
}

void DeckReader::on_conductivity(const KeywordLine& kw) {
  Material& m = current_material(kw);
  bool orthotropic = false;
  if (const Parameter* type = kw.find("TYPE")) {
    const std::string value = normalize_name(type->value);
    if (value != "ISO" && value != "ORTHO")
      throw InputError(kw.where, kw.label() + ", TYPE=" + type->value +
                                     " is not supported; Styk reads TYPE=ISO (default) and "
                                     "TYPE=ORTHO (k11, k22, k33 in global axes)");
    orthotropic = value == "ORTHO";
  }
  const bool electrical = kw.name == "ELECTRICAL CONDUCTIVITY";
  std::optional<std::array<double, 3>>& target =
      electrical ? m.electrical_conductivity : m.conductivity;
  if (target)
    throw InputError(kw.where, "material " + m.name + " has two " + kw.label() + " blocks");
  const std::string layout = orthotropic ? "k11, k22, k33" : "k";
  const std::optional<DataLine> line = single_data_line(kw, true, layout);
  const std::size_t fields = orthotropic ? 3 : 1;
  expect_fields(*line, fields, fields, layout + " (temperature-dependent data is not supported)");
  target = read_conductivity(*line, orthotropic,
                             electrical ? "electrical conductivity" : "conductivity");
}

void DeckReader::read_scalar_loads(const KeywordLine& kw, int dof) {
  Step& step = current_step();
  if (op_new(kw)) step.cflux_op_new = true;
  while (std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 3, 3, "node or node set, dof " + std::to_string(dof) + ", value");
    const std::vector<int> nodes = nodes_of(*line, 0, "node or node set");
    const std::int64_t given = integer_field(*line, 1, "dof");
    if (given != dof)
      throw InputError(line->where, kw.label() + " acts on " + dof_name(dof) + ", read dof " +
                                        std::to_string(given));
    const double value = real_field(*line, 2, "value");
    for (int node : nodes) step.cfluxes.push_back({node, dof, value, line->where});
  }
}

void DeckReader::on_cflux(const KeywordLine& kw) { read_scalar_loads(kw, 11); }

void DeckReader::on_cecur(const KeywordLine& kw) { read_scalar_loads(kw, 9); }

void DeckReader::on_dflux(const KeywordLine& kw) {
  Step& step = current_step();
  if (op_new(kw)) step.dflux_op_new = true;
  while (std::optional<DataLine> line = next_data_line()) {
    const std::string label = line->fields.size() > 1 ? normalize_name(line->fields[1]) : "";
    const bool face_label =
        label.size() == 2 && label[0] == 'S' && label[1] >= '1' && label[1] <= '6';
    if (line->fields.size() > 1 && !face_label)
      throw InputError(line->where, "flux label " + quote(line->fields[1]) +
                                        " is not supported; Styk reads uniform face fluxes "
                                        "S1..S6");
    expect_fields(*line, 3, 3, "element or element set, face label S1..S6, flux");
    const std::vector<int> elements = elements_of(*line, 0, "element or element set");
    const double magnitude = real_field(*line, 2, "flux");
    for (int e : elements) step.dfluxes.push_back({e, label[1] - '0', magnitude, line->where});
  }
}

void DeckReader::check_field_kinds() {
  // Every step's own data must match its procedure.
  for (const Step& step : model_.steps) {
    for (const Boundary& b : step.boundaries)
      if (!dof_fits(b.dof, step.kind))
        throw InputError(b.where, dof_name(b.dof) + " in a " + procedure_keyword(step.kind) +
                                      " step (at " + step.procedure.where.str() +
                                      "): " + what_step_takes(step.kind));
    const bool scalar = step.kind != StepKind::Static;
    if (scalar && !step.cloads.empty())
      throw InputError(step.cloads.front().where,
                       std::string("*CLOAD in a ") + procedure_keyword(step.kind) +
                           " step: use *CFLUX (heat flow) or *CECUR (current)");
    if (scalar && !step.dloads.empty())
      throw InputError(step.dloads.front().where, std::string("*DLOAD in a ") +
                                                      procedure_keyword(step.kind) +
                                                      " step: use *DFLUX for a face flux");
    if (scalar && !step.temperatures.empty())
      throw InputError(step.temperatures.front().where,
                       std::string("*TEMPERATURE in a ") + procedure_keyword(step.kind) +
                           " step: the temperature is the unknown there; prescribe it with "
                           "*BOUNDARY, dof 11");
    for (const ConcentratedLoad& c : step.cfluxes)
      if (!dof_fits(c.dof, step.kind))
        throw InputError(c.where, std::string(c.dof == 11 ? "*CFLUX" : "*CECUR") + " in a " +
                                      procedure_keyword(step.kind) + " step (at " +
                                      step.procedure.where.str() +
                                      "): " + what_step_takes(step.kind));
    for (const OutputRequest& request : step.outputs)
      for (const std::string& var : request.vars)
        if (!variable_fits(var, step.kind))
          throw InputError(request.where, "output variable " + var + " in a " +
                                              procedure_keyword(step.kind) + " step: it prints " +
                                              variables_of(step.kind));
    if (step.kind != StepKind::HeatTransfer && !step.dfluxes.empty())
      throw InputError(step.dfluxes.front().where,
                       std::string("*DFLUX in a ") + procedure_keyword(step.kind) +
                           " step: face fluxes belong to *HEAT TRANSFER steps");
  }
  // Model-level boundary conditions hold in every step, so they must fit every step.
  for (const Boundary& b : model_.boundaries)
    for (const Step& step : model_.steps)
      if (!dof_fits(b.dof, step.kind))
        throw InputError(b.where, dof_name(b.dof) + " is prescribed for every step, but the " +
                                      procedure_keyword(step.kind) + " step at " +
                                      step.procedure.where.str() +
                                      " cannot take it: " + what_step_takes(step.kind));
  // Materials: what the deck's procedures need (the old "no *ELASTIC" check for static decks).
  bool needs_elastic = false, needs_heat = false, needs_electric = false;
  for (const Step& step : model_.steps) {
    needs_elastic |= step.kind == StepKind::Static;
    needs_heat |= step.kind == StepKind::HeatTransfer;
    needs_electric |= step.kind == StepKind::ElectricConduction;
  }
  for (const Material& m : model_.materials) {
    if (needs_elastic && !m.has_elasticity())
      throw InputError(m.where, "material " + m.name + " has no *ELASTIC constants");
    if (needs_heat && !m.conductivity)
      throw InputError(m.where, "material " + m.name +
                                    " has no *CONDUCTIVITY, which the *HEAT TRANSFER step needs");
    if (needs_electric && !m.electrical_conductivity)
      throw InputError(m.where, "material " + m.name +
                                    " has no *ELECTRICAL CONDUCTIVITY, which the *COUPLED "
                                    "THERMAL-ELECTRICAL step needs");
  }
}

}  // namespace styk::inp
