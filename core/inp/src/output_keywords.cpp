// The output requests' parameters beyond the set (TOTALS, GLOBAL, FREQUENCY), the element
// variables each request takes, and *SECTION PRINT. (*NODE PRINT, *EL PRINT, *NODE FILE and
// *EL FILE themselves: step_keywords.cpp.)
#include <algorithm>

#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {

namespace {

bool yes_no(const Parameter& p, const KeywordLine& kw) {
  const std::string value = normalize_name(p.value);
  if (value == "YES") return true;
  if (value == "NO") return false;
  throw InputError(kw.where, p.name + "=" + p.value + " on " + kw.label() + ": expected YES or NO");
}

bool has(const std::vector<std::string>& vars, const char* name) {
  return std::find(vars.begin(), vars.end(), name) != vars.end();
}

}  // namespace

std::vector<std::string> DeckReader::element_output_variables(OutputRequest::Kind kind) {
  if (kind == OutputRequest::Kind::ElementPrint)
    return {"S", "E", "SF", "SM", "HFL", "ECD", "ENER", "ELSE", "EVOL", "CENT"};
  return {"S", "E", "SF", "SM", "HFL", "ECD", "ENER", "THE", "ERR", "NOE"};
}

void DeckReader::read_output_parameters(const KeywordLine& kw, OutputRequest& request) const {
  if (const Parameter* totals = kw.find("TOTALS")) {
    const std::string value = normalize_name(totals->value);
    if (value != "YES" && value != "NO" && value != "ONLY")
      throw InputError(kw.where, "TOTALS=" + totals->value + ": expected YES, NO or ONLY");
    request.totals = value != "NO";
    request.totals_only = value == "ONLY";
  }
  if (const Parameter* global = kw.find("GLOBAL")) request.global = yes_no(*global, kw);
  // CalculiX: OUTPUT=2D|3D chooses whether the .frd shows plane, axisymmetric, beam and shell
  // elements as drawn or as their 3D expansion. Styk never expands them (its results hold the
  // elements as defined), so both values describe what it writes.
  if (const Parameter* output = kw.find("OUTPUT")) {
    const std::string value = normalize_name(output->value);
    if (value != "2D" && value != "3D")
      throw InputError(kw.where,
                       "OUTPUT=" + output->value + " of " + kw.label() + ": expected 2D or 3D");
  }
  for (const char* name : {"FREQUENCY", "FREQUENCYF"})
    if (const Parameter* frequency = kw.find(name)) {
      const std::int64_t n = integer_value(frequency->value, std::string(name) + "=", kw.where);
      if (n < 0 || n > 1000000000)
        throw InputError(kw.where, std::string(name) + "=" + frequency->value +
                                       ": expected an increment count >= 0 (0: no output)");
      request.frequency = static_cast<int>(n);
    }
}

void DeckReader::complete_element_variables(const KeywordLine& kw, OutputRequest& request) const {
  if (request.kind != OutputRequest::Kind::ElementFile) return;
  // CalculiX: S on *EL FILE brings the error estimator ERR along unless NOE follows it, on this
  // card or a later one (the results consumers apply that rule; here NOE must follow some S).
  if (!has(request.vars, "NOE") || has(request.vars, "S")) return;
  bool earlier_stress = false;
  for (const OutputRequest& other : model_.steps.back().outputs)
    earlier_stress =
        earlier_stress || (other.kind == OutputRequest::Kind::ElementFile && has(other.vars, "S"));
  if (!earlier_stress)
    throw InputError(kw.where, "NOE (no error estimator) on " + kw.label() +
                                   " follows no S (stress) request of this step");
}

void DeckReader::on_section_print(const KeywordLine& kw) {
  OutputRequest request;
  request.kind = OutputRequest::Kind::SectionPrint;
  request.where = kw.where;
  request.set = normalize_name(kw.find("SURFACE")->value);
  request.name = kw.find("NAME")->value;
  const auto surface = model_.surfaces.find(request.set);
  if (surface == model_.surfaces.end())
    throw InputError(kw.where, "SURFACE=" + request.set +
                                   " of *SECTION PRINT is not defined; "
                                   "surfaces: " +
                                   some_names(model_.surfaces));
  if (surface->second.kind != Surface::Kind::ElementFaces)
    throw InputError(kw.where, "SURFACE=" + request.set +
                                   " of *SECTION PRINT is a node surface; section forces need "
                                   "element faces");
  read_output_parameters(kw, request);
  const std::vector<std::string> allowed{"SOF", "SOM", "SOAREA"};
  while (std::optional<DataLine> line = next_data_line())
    for (const std::string& field : line->fields) {
      if (field.empty()) continue;
      const std::string var = normalize_name(field);
      if (!has(allowed, var.c_str()))
        throw InputError(line->where, "output variable " + quote(field) +
                                          " is not supported by *SECTION PRINT; Styk writes SOF, "
                                          "SOM and SOAREA (all three give the whole section "
                                          "report)");
      if (!has(request.vars, var.c_str())) request.vars.push_back(var);
    }
  if (request.vars.empty())
    throw InputError(kw.where,
                     "*SECTION PRINT needs a data line naming the variables (SOF, "
                     "SOM, SOAREA)");
  current_step().outputs.push_back(std::move(request));
}

}  // namespace styk::inp
