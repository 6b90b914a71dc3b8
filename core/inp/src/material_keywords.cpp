// *ELASTIC and *EXPANSION: the material law's constants by type (isotropic, orthotropic,
// engineering constants, anisotropic) and their tables over temperature.
#include <algorithm>

#include "deck_reader.hpp"
#include "numbers.hpp"
#include "styk/core/constitutive.hpp"

namespace styk::inp {

namespace {

// CalculiX/Abaqus data lines of a material table hold at most 8 fields; a record longer than
// that continues on the next line.
constexpr std::size_t kFieldsPerLine = 8;

struct TableLayout {
  std::size_t count = 0;  // constants per row (the temperature follows them)
  std::string names;      // "E, nu" for messages
};

TableLayout elastic_layout(ElasticType type) {
  switch (type) {
    case ElasticType::Isotropic:
      return {2, "E, nu"};
    case ElasticType::Orthotropic:
      return {9, "D1111, D1122, D2222, D1133, D2233, D3333, D1212, D1313, D2323"};
    case ElasticType::EngineeringConstants:
      return {9, "E1, E2, E3, nu12, nu13, nu23, G12, G13, G23"};
    case ElasticType::Anisotropic:
      return {21,
              "D1111, D1122, D2222, D1133, D2233, D3333, D1112, D2212, D3312, D1212, D1113, "
              "D2213, D3313, D1213, D1313, D1123, D2223, D3323, D1223, D1323, D2323"};
  }
  return {};
}

TableLayout expansion_layout(ExpansionType type) {
  switch (type) {
    case ExpansionType::Isotropic:
      return {1, "alpha"};
    case ExpansionType::Orthotropic:
      return {3, "alpha11, alpha22, alpha33"};
    case ExpansionType::Anisotropic:
      return {6, "alpha11, alpha22, alpha33, alpha12, alpha13, alpha23"};
  }
  return {};
}

ElasticType elastic_type(const KeywordLine& kw) {
  const Parameter* type = kw.find("TYPE");
  if (!type) return ElasticType::Isotropic;
  const std::string value = normalize_name(type->value);
  if (value == "ISO" || value == "ISOTROPIC") return ElasticType::Isotropic;
  if (value == "ORTHO" || value == "ORTHOTROPIC") return ElasticType::Orthotropic;
  if (value == "ENGINEERING CONSTANTS") return ElasticType::EngineeringConstants;
  if (value == "ANISO" || value == "ANISOTROPIC") return ElasticType::Anisotropic;
  throw InputError(kw.where, "*ELASTIC, TYPE=" + type->value +
                                 " is not known; Styk reads ISOTROPIC (ISO), ORTHOTROPIC (ORTHO), "
                                 "ENGINEERING CONSTANTS and ANISOTROPIC (ANISO)");
}

ExpansionType expansion_type(const KeywordLine& kw) {
  const Parameter* type = kw.find("TYPE");
  if (!type) return ExpansionType::Isotropic;
  const std::string value = normalize_name(type->value);
  if (value == "ISO" || value == "ISOTROPIC") return ExpansionType::Isotropic;
  if (value == "ORTHO" || value == "ORTHOTROPIC") return ExpansionType::Orthotropic;
  if (value == "ANISO" || value == "ANISOTROPIC") return ExpansionType::Anisotropic;
  throw InputError(kw.where, "*EXPANSION, TYPE=" + type->value +
                                 " is not known; Styk reads ISO, ORTHO and ANISO");
}

}  // namespace

std::vector<MaterialTableRow> DeckReader::read_material_table(const KeywordLine& kw,
                                                              std::size_t count,
                                                              const std::string& names,
                                                              std::vector<SourceLoc>* lines) {
  const std::string layout = names + "[, temperature]";
  std::vector<MaterialTableRow> rows;
  std::vector<std::string> fields;
  SourceLoc first_line;
  while (std::optional<DataLine> line = next_data_line()) {
    if (fields.empty()) first_line = line->where;
    fields.insert(fields.end(), line->fields.begin(), line->fields.end());
    // A row that fits on one line must be complete on it.
    if (count + 1 <= kFieldsPerLine && fields.size() < count)
      throw InputError(line->where, kw.label() + " data line has " + std::to_string(fields.size()) +
                                        " field" + (fields.size() == 1 ? "" : "s") + ", expected " +
                                        layout);
    if (fields.size() < count) {
      // Not the last line of the record: it must be full (8 fields) for the record to go on.
      if (line->fields.size() != kFieldsPerLine)
        throw InputError(line->where, kw.label() + " data line has " +
                                          std::to_string(line->fields.size()) +
                                          " fields; a row holds " + layout + ", " +
                                          std::to_string(kFieldsPerLine) +
                                          " fields per line, continued on the next line");
      continue;
    }
    if (fields.size() > count + 1)
      throw InputError(line->where, kw.label() + " row has " + std::to_string(fields.size()) +
                                        " fields, expected " + layout);
    const DataLine record{fields, false, first_line};
    MaterialTableRow row;
    for (std::size_t i = 0; i < count; ++i)
      row.values.push_back(
          real_field(record, i, "constant " + std::to_string(i + 1) + " (" + names + ")"));
    const bool has_temperature = fields.size() == count + 1 && !fields[count].empty();
    row.temperature = has_temperature ? real_field(record, count, "temperature") : 0.0;
    if (!rows.empty() && !has_temperature)
      throw InputError(first_line, kw.label() +
                                       ": every row of a table over temperature needs "
                                       "its temperature (the field after " +
                                       names + ")");
    if (!rows.empty() && !(row.temperature > rows.back().temperature))
      throw InputError(first_line, kw.label() + ": temperatures must increase from row to row (" +
                                       fields[count] + " follows a row at " +
                                       std::to_string(rows.back().temperature) + ")");
    rows.push_back(std::move(row));
    if (lines) lines->push_back(first_line);
    fields.clear();
  }
  if (!fields.empty())
    throw InputError(first_line, kw.label() + " row is incomplete: " +
                                     std::to_string(fields.size()) + " fields, expected " + layout);
  if (rows.empty()) throw InputError(kw.where, kw.label() + " needs a data line: " + layout);
  return rows;
}

void DeckReader::on_elastic(const KeywordLine& kw) {
  Material& m = current_material(kw);
  if (m.has_elasticity())
    throw InputError(kw.where, "material " + m.name + " has two *ELASTIC blocks");
  const ElasticType type = elastic_type(kw);
  const TableLayout layout = elastic_layout(type);
  std::vector<SourceLoc> lines;
  std::vector<MaterialTableRow> rows = read_material_table(kw, layout.count, layout.names, &lines);
  // Each row must define a law: checked on its own, reported at its line.
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Material single = m;
    single.elastic_type = type;
    single.elastic_table = {rows[i]};
    try {
      check_elasticity(single);
    } catch (const InputError& e) {
      throw InputError(lines[i], e.message());
    }
  }
  m.elastic_type = type;
  if (type == ElasticType::Isotropic && rows.size() == 1) {
    // The constant isotropic law: E and nu, as every consumer of the model reads it.
    m.young = rows.front().values[0];
    m.poisson = rows.front().values[1];
  } else {
    m.elastic_table = std::move(rows);
  }
}

void DeckReader::on_expansion(const KeywordLine& kw) {
  Material& m = current_material(kw);
  if (m.has_expansion())
    throw InputError(kw.where, "material " + m.name + " has two *EXPANSION blocks");
  const ExpansionType type = expansion_type(kw);
  if (const Parameter* zero = kw.find("ZERO"))
    m.expansion_reference = real_value(zero->value, "ZERO= of *EXPANSION", kw.where);
  const TableLayout layout = expansion_layout(type);
  std::vector<MaterialTableRow> rows = read_material_table(kw, layout.count, layout.names);
  m.expansion_type = type;
  if (type == ExpansionType::Isotropic && rows.size() == 1)
    m.expansion = rows.front().values[0];
  else
    m.expansion_table = std::move(rows);
}

}  // namespace styk::inp
