// The material law in a written deck: *ELASTIC and *EXPANSION with their types and tables.
#include "writer_parts.hpp"

namespace styk::inp {

namespace {

// A material table: each row's constants and its temperature, 8 fields per line.
void write_table(const std::vector<MaterialTableRow>& rows, std::ostream& out) {
  constexpr std::size_t kFieldsPerLine = 8;
  for (const MaterialTableRow& row : rows) {
    std::vector<double> fields = row.values;
    fields.push_back(row.temperature);
    for (std::size_t i = 0; i < fields.size(); ++i) {
      out << shortest_number(fields[i]);
      const bool end = i + 1 == fields.size() || (i + 1) % kFieldsPerLine == 0;
      out << (end ? "\n" : ", ");
    }
  }
}

const char* elastic_type_name(ElasticType type) {
  switch (type) {
    case ElasticType::Isotropic:
      return "ISO";
    case ElasticType::Orthotropic:
      return "ORTHO";
    case ElasticType::EngineeringConstants:
      return "ENGINEERING CONSTANTS";
    case ElasticType::Anisotropic:
      return "ANISO";
  }
  return "ISO";
}

const char* expansion_type_name(ExpansionType type) {
  switch (type) {
    case ExpansionType::Isotropic:
      return "ISO";
    case ExpansionType::Orthotropic:
      return "ORTHO";
    case ExpansionType::Anisotropic:
      return "ANISO";
  }
  return "ISO";
}

}  // namespace

void write_material_law(const Material& m, std::ostream& out) {
  if (m.young && m.poisson) {
    out << "*ELASTIC\n" << shortest_number(*m.young) << ", " << shortest_number(*m.poisson) << '\n';
  } else if (!m.elastic_table.empty()) {
    out << "*ELASTIC, TYPE=" << elastic_type_name(m.elastic_type) << '\n';
    write_table(m.elastic_table, out);
  }
  if (m.density) out << "*DENSITY\n" << shortest_number(*m.density) << '\n';
  if (m.expansion) {
    out << "*EXPANSION, ZERO=" << shortest_number(m.expansion_reference) << '\n'
        << shortest_number(*m.expansion) << '\n';
  } else if (!m.expansion_table.empty()) {
    out << "*EXPANSION, TYPE=" << expansion_type_name(m.expansion_type)
        << ", ZERO=" << shortest_number(m.expansion_reference) << '\n';
    write_table(m.expansion_table, out);
  }
}

}  // namespace styk::inp
