// *STEP, *STATIC, *END STEP, *BOUNDARY, *CLOAD, *DLOAD and the output requests.
// (*HEAT TRANSFER, *COUPLED THERMAL-ELECTRICAL and their loads: scalar_keywords.cpp.)
#include <algorithm>

#include "deck_reader.hpp"
#include "numbers.hpp"
#include "writer_parts.hpp"

namespace styk::inp {

namespace {

// OP=NEW|MOD; true for NEW.
bool op_new(const KeywordLine& kw, bool in_step) {
  const Parameter* op = kw.find("OP");
  if (!op) return false;
  const std::string value = normalize_name(op->value);
  if (value == "MOD") return false;
  if (value != "NEW")
    throw InputError(kw.where, "OP=" + op->value + " on " + kw.label() + ": expected NEW or MOD");
  if (!in_step)
    throw InputError(kw.where, "OP=NEW on " + kw.label() + " is only meaningful inside a step");
  return true;
}

bool is_integer_text(const std::string& text) { return looks_like_integer(text); }

LinearSolverKind solver_kind(const Parameter& p, const SourceLoc& where) {
  const std::string value = normalize_name(p.value);
  if (value == "DEFAULT") return LinearSolverKind::Automatic;
  if (value == "CHOLMOD" || value == "SPOOLES" || value == "PARDISO")
    return LinearSolverKind::Cholmod;
  if (value == "ITERATIVE CHOLESKY" || value == "ITERATIVE SCALING" || value == "AMG")
    return LinearSolverKind::Iterative;
  throw InputError(where, "SOLVER=" + p.value +
                              " is not known; expected DEFAULT, CHOLMOD, SPOOLES, PARDISO "
                              "(direct), AMG, ITERATIVE CHOLESKY or ITERATIVE SCALING (iterative)");
}

}  // namespace

void DeckReader::on_step(const KeywordLine& kw) {
  if (const Parameter* nlgeom = kw.find("NLGEOM")) {
    const std::string value = normalize_name(nlgeom->value);
    if (!nlgeom->has_value || value == "YES")
      throw InputError(kw.where,
                       "NLGEOM: geometric nonlinearity is not supported (Styk solves "
                       "small-displacement problems); remove NLGEOM or set NLGEOM=NO");
    if (value != "NO")
      throw InputError(kw.where, "NLGEOM=" + nlgeom->value + ": expected YES or NO");
  }
  if (const Parameter* inc = kw.find("INC")) {
    if (integer_value(inc->value, "INC= of *STEP", kw.where) < 1)
      throw InputError(kw.where, "INC= of *STEP must be a positive integer, read " + inc->value);
  }
  Step step;
  if (const Parameter* name = kw.find("NAME")) step.name = name->value;
  step.where = kw.where;
  model_.steps.push_back(std::move(step));
  in_step_ = true;
}

void DeckReader::on_static(const KeywordLine& kw) {
  Step& step = current_step();
  if (step.has_procedure)
    throw InputError(kw.where, "this step already has a procedure (at " +
                                   step.procedure.where.str() + "); one per step");
  StaticProcedure proc;
  proc.where = kw.where;
  if (const Parameter* solver = kw.find("SOLVER")) proc.solver = solver_kind(*solver, kw.where);
  const std::string layout = "initial increment, step time, minimum increment, maximum increment";
  if (const std::optional<DataLine> line = single_data_line(kw, false, layout)) {
    expect_fields(*line, 0, 4, layout);
    const char* names[] = {"initial increment", "step time", "minimum increment",
                           "maximum increment"};
    double values[4] = {1.0, 1.0, 0.0, 0.0};
    for (std::size_t i = 0; i < line->fields.size(); ++i) {
      if (line->fields[i].empty()) continue;
      values[i] = real_field(*line, i, names[i]);
      if (values[i] <= 0.0)
        throw InputError(line->where,
                         std::string(names[i]) + " must be positive, read " + line->fields[i]);
    }
    // A value as read, or the default it took (a data line may leave a field empty or out).
    auto shown = [&](std::size_t i) {
      return i < line->fields.size() && !line->fields[i].empty()
                 ? line->fields[i]
                 : shortest_number(values[i]) + ", the default";
    };
    if (values[0] > values[1])
      throw InputError(line->where, "the initial increment (" + shown(0) +
                                        ") is larger than the step time (" + shown(1) + ")");
    proc.initial_increment = values[0];
    proc.total_time = values[1];
    if (line->fields.size() > 2 && !line->fields[2].empty()) proc.min_increment = values[2];
    if (line->fields.size() > 3 && !line->fields[3].empty()) proc.max_increment = values[3];
    if (proc.min_increment && proc.max_increment && values[2] > values[3])
      throw InputError(line->where, "the minimum increment (" + line->fields[2] +
                                        ") is larger than the maximum increment (" +
                                        line->fields[3] + ")");
  }
  proc.fixed_increments = kw.find("DIRECT") != nullptr;  // DIRECT: no automatic incrementation
  step.procedure = proc;
  step.has_procedure = true;
}

void DeckReader::on_end_step(const KeywordLine& kw) {
  if (!current_step().has_procedure)
    throw InputError(kw.where, "the step (at " + current_step().where.str() +
                                   ") has no procedure; add *STATIC, *HEAT TRANSFER or *COUPLED "
                                   "THERMAL-ELECTRICAL");
  in_step_ = false;
}

void DeckReader::on_boundary(const KeywordLine& kw) {
  const bool fresh = op_new(kw, in_step_);
  // FIXED: hold the displacement of the end of the previous step (CalculiX), step data only.
  const bool fixed = kw.find("FIXED") != nullptr;
  if (fixed && !in_step_)
    throw InputError(kw.where,
                     "*BOUNDARY, FIXED holds the displacements of the previous step: "
                     "it belongs inside a step");
  std::vector<Boundary>& target = in_step_ ? current_step().boundaries : model_.boundaries;
  if (in_step_ && fresh) current_step().boundary_op_new = true;
  while (std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 2, 4, "node or node set, first dof, last dof, value");
    if (!is_integer_text(line->fields[1]))
      throw InputError(line->where,
                       "field 2 (first dof): expected an integer, read " + quote(line->fields[1]) +
                           " (named boundary types such as ENCASTRE are not supported; "
                           "give the dofs, e.g. 'SET, 1, 3')");
    const std::vector<int> nodes = nodes_of(*line, 0, "node or node set");
    const int first = boundary_dof(*line, 1, "first dof");
    const bool has_last = line->fields.size() > 2 && !line->fields[2].empty();
    const int last = has_last ? boundary_dof(*line, 2, "last dof") : first;
    if ((first > 6 || last > 6) && last != first)
      throw InputError(line->where, "dofs " + std::to_string(first) + " to " +
                                        std::to_string(last) +
                                        ": a scalar-field dof (9, 11) is given alone, e.g. '" +
                                        std::to_string(std::max(first, last)) + ", " +
                                        std::to_string(std::max(first, last)) + "'");
    if (last < first)
      throw InputError(line->where, "last dof " + std::to_string(last) +
                                        " is smaller than first dof " + std::to_string(first));
    const bool has_value = line->fields.size() > 3 && !line->fields[3].empty();
    if (fixed && has_value)
      throw InputError(line->where,
                       "*BOUNDARY, FIXED takes no value: the dofs keep the "
                       "displacement of the end of the previous step");
    if (fixed && last > 3)
      throw InputError(line->where, "*BOUNDARY, FIXED holds displacements (dofs 1..3)");
    const double value = has_value ? real_field(*line, 3, "value") : 0.0;
    for (int node : nodes)
      for (int dof = first; dof <= last; ++dof)
        target.push_back({node, dof, value, line->where, fixed});
  }
}

void DeckReader::on_cload(const KeywordLine& kw) {
  Step& step = current_step();
  if (op_new(kw, true)) step.cload_op_new = true;
  while (std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 3, 3, "node or node set, dof, value");
    const std::vector<int> nodes = nodes_of(*line, 0, "node or node set");
    const int dof = load_dof(*line);  // coupling_keywords.cpp: moments 4..6
    const double value = real_field(*line, 2, "value");
    for (int node : nodes) step.cloads.push_back({node, dof, value, line->where});
  }
}

// The label P (without a face number) is the pressure of shell elements only.
void DeckReader::check_shell_pressure(const Element& element, const SourceLoc& where) const {
  const TElement* formulation = registry_.find(element.type);
  if (formulation != nullptr && formulation->section_measure() == SectionMeasure::Shell) return;
  throw InputError(where, "load label P (a shell pressure) on element " +
                              std::to_string(element.id) + " (" + element.type +
                              "), which is not a shell; faces of solids take P1..P6");
}

void DeckReader::on_dload(const KeywordLine& kw) {
  Step& step = current_step();
  if (op_new(kw, true)) step.dload_op_new = true;
  while (std::optional<DataLine> line = next_data_line()) {
    // The label first: other load types (GRAV, CENTRIF, BX...) have a different field layout.
    const std::string label = line->fields.size() > 1 ? normalize_name(line->fields[1]) : "";
    if (label == "GRAV" || label == "CENTRIF") {
      read_body_load(*line, label);  // load_keywords.cpp
      continue;
    }
    const bool face_label =
        label.size() == 2 && label[0] == 'P' && label[1] >= '1' && label[1] <= '6';
    const bool shell_pressure = label == "P";  // shells: pressure on the reference surface
    if (line->fields.size() > 1 && !face_label && !shell_pressure)
      throw InputError(line->where, "load label " + quote(line->fields[1]) +
                                        " is not supported; Styk reads face pressures P1..P6, "
                                        "the shell pressure P, GRAV and CENTRIF");
    expect_fields(*line, 3, 3, "element or element set, load label, magnitude");
    const std::vector<int> elements = elements_of(*line, 0, "element or element set");
    const double magnitude = real_field(*line, 2, "magnitude");
    for (int e : elements) {
      if (shell_pressure) check_shell_pressure(model_.elements[e], line->where);
      step.dloads.push_back({e, shell_pressure ? 1 : label[1] - '0', magnitude, line->where});
    }
  }
}

void DeckReader::read_output(const KeywordLine& kw, OutputRequest::Kind kind) {
  using K = OutputRequest::Kind;
  const bool nodal = kind == K::NodePrint || kind == K::NodeFile;
  // Scalar-field variables (NT, RFL, HFL heat; EPOT, RECUR, ECD electric) are matched with the
  // step's procedure once the deck is complete (scalar_keywords.cpp).
  // Element output: ENER (energy density), ELSE (element energy), EVOL (volume), CENT (omega^2
  // of a CENTRIF load) print; THE (thermal strain), ERR (error estimator) and NOE (no ERR) go
  // to the results file (output_keywords.cpp checks which keyword takes which).
  const std::vector<std::string> allowed =
      nodal ? std::vector<std::string>{"U", "RF", "UR", "RM", "NT", "RFL", "EPOT", "RECUR"}
            : element_output_variables(kind);
  OutputRequest request;
  request.kind = kind;
  request.where = kw.where;
  if (nodal && kw.find("NSET")) {
    request.set = set_name(kw, "NSET");
    if (!model_.find_nset(request.set))
      throw InputError(kw.where, "NSET=" + request.set + " of " + kw.label() +
                                     " is not defined; node sets: " + some_names(model_.nsets));
  }
  if (!nodal && kw.find("ELSET")) {
    request.set = set_name(kw, "ELSET");
    if (!model_.find_elset(request.set))
      throw InputError(kw.where, "ELSET=" + request.set + " of " + kw.label() +
                                     " is not defined; element sets: " + some_names(model_.elsets));
  }
  read_output_parameters(kw, request);  // TOTALS, GLOBAL, FREQUENCY (output_keywords.cpp)
  if (const Parameter* position = kw.find("POSITION")) {  // *EL PRINT only (Abaqus spelling)
    using P = OutputRequest::Position;
    const std::string value = normalize_name(position->value);
    if (value == "INTEGRATION POINTS")
      request.position = P::IntegrationPoints;
    else if (value == "CENTROIDAL")
      request.position = P::Centroidal;
    else if (value == "AVERAGED AT NODES")
      request.position = P::AveragedAtNodes;
    else
      throw InputError(kw.where, "POSITION=" + position->value + " of " + kw.label() +
                                     ": expected INTEGRATION POINTS, CENTROIDAL or AVERAGED AT "
                                     "NODES");
  }
  std::string list;
  for (const std::string& name : allowed) list += (list.empty() ? "" : ", ") + name;
  while (std::optional<DataLine> line = next_data_line()) {
    for (const std::string& field : line->fields) {
      if (field.empty()) continue;
      const std::string var = normalize_name(field);
      if (std::find(allowed.begin(), allowed.end(), var) == allowed.end())
        throw InputError(line->where, "output variable " + quote(field) + " is not supported by " +
                                          kw.label() + "; Styk writes " + list);
      if (std::find(request.vars.begin(), request.vars.end(), var) == request.vars.end())
        request.vars.push_back(var);
    }
  }
  if (request.vars.empty())
    throw InputError(kw.where,
                     kw.label() + " needs a data line naming the variables (" + list + ")");
  complete_element_variables(kw, request);  // *EL FILE: S brings ERR unless NOE follows
  current_step().outputs.push_back(std::move(request));
}

void DeckReader::on_node_print(const KeywordLine& kw) {
  read_output(kw, OutputRequest::Kind::NodePrint);
}
void DeckReader::on_el_print(const KeywordLine& kw) {
  read_output(kw, OutputRequest::Kind::ElementPrint);
}
void DeckReader::on_node_file(const KeywordLine& kw) {
  read_output(kw, OutputRequest::Kind::NodeFile);
}
void DeckReader::on_el_file(const KeywordLine& kw) {
  read_output(kw, OutputRequest::Kind::ElementFile);
}

}  // namespace styk::inp
