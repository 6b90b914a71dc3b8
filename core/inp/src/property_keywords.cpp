// *MATERIAL, *ELASTIC, *DENSITY, *EXPANSION, *SOLID SECTION.
#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {

Material& DeckReader::current_material(const KeywordLine& kw) {
  if (material_ < 0)
    throw InputError(kw.where, kw.label() +
                                   " must follow *MATERIAL (it belongs to the material "
                                   "defined just above it)");
  return model_.materials[material_];
}

void DeckReader::on_material(const KeywordLine& kw) {
  const std::string name = normalize_name(kw.find("NAME")->value);
  const int existing = model_.material_index(name);
  if (existing >= 0)
    throw InputError(kw.where, "material " + name + " is defined twice (first at " +
                                   model_.materials[existing].where.str() + ")");
  Material m;
  m.name = name;
  m.where = kw.where;
  model_.materials.push_back(std::move(m));
  material_ = static_cast<int>(model_.materials.size()) - 1;
}

void DeckReader::on_elastic(const KeywordLine& kw) {
  Material& m = current_material(kw);
  if (const Parameter* type = kw.find("TYPE"); type && normalize_name(type->value) != "ISOTROPIC")
    throw InputError(kw.where, "*ELASTIC, TYPE=" + type->value +
                                   " is not supported; Styk reads TYPE=ISOTROPIC only");
  if (m.young) throw InputError(kw.where, "material " + m.name + " has two *ELASTIC blocks");
  const std::optional<DataLine> line = single_data_line(kw, true, "E, nu");
  expect_fields(*line, 2, 2, "E, nu (temperature-dependent data is not supported)");
  const double young = real_field(*line, 0, "Young's modulus E");
  const double poisson = real_field(*line, 1, "Poisson's ratio nu");
  if (young <= 0.0)
    throw InputError(line->where, "Young's modulus must be positive, read " + line->fields[0]);
  if (poisson <= -1.0 || poisson >= 0.5)
    throw InputError(line->where, "Poisson's ratio must lie in (-1, 0.5), read " + line->fields[1]);
  m.young = young;
  m.poisson = poisson;
}

void DeckReader::on_density(const KeywordLine& kw) {
  Material& m = current_material(kw);
  const std::optional<DataLine> line = single_data_line(kw, true, "density");
  expect_fields(*line, 1, 1, "density (temperature-dependent data is not supported)");
  const double rho = real_field(*line, 0, "density");
  if (rho <= 0.0)
    throw InputError(line->where, "density must be positive, read " + line->fields[0]);
  m.density = rho;
}

void DeckReader::on_expansion(const KeywordLine& kw) {
  Material& m = current_material(kw);
  if (const Parameter* type = kw.find("TYPE"); type && normalize_name(type->value) != "ISO")
    throw InputError(kw.where, "*EXPANSION, TYPE=" + type->value +
                                   " is not supported; Styk reads TYPE=ISO only");
  if (const Parameter* zero = kw.find("ZERO"))
    m.expansion_reference = real_value(zero->value, "ZERO= of *EXPANSION", kw.where);
  const std::optional<DataLine> line = single_data_line(kw, true, "alpha");
  expect_fields(*line, 1, 1, "alpha (temperature-dependent data is not supported)");
  m.expansion = real_field(*line, 0, "expansion coefficient alpha");
}

void DeckReader::on_solid_section(const KeywordLine& kw) {
  Section section;
  section.elset = set_name(kw, "ELSET");
  section.material = normalize_name(kw.find("MATERIAL")->value);
  section.where = kw.where;
  // Styk-only TECHNIQUE=SELECTIVE: mean-dilatation B-bar against volumetric locking.
  if (const Parameter* technique = kw.find("TECHNIQUE")) {
    const std::string value = normalize_name(technique->value);
    if (value != "SELECTIVE" && value != "FULL")
      throw InputError(kw.where, "*SOLID SECTION, TECHNIQUE=" + technique->value +
                                     " is not known; Styk reads FULL (default) or SELECTIVE");
    section.selective_volumetric = value == "SELECTIVE";
  }
  if (const std::optional<DataLine> line = single_data_line(kw, false, "thickness")) {
    expect_fields(*line, 1, 1, "thickness");
    const double t = real_field(*line, 0, "thickness");
    if (t <= 0.0)
      throw InputError(line->where, "thickness must be positive, read " + line->fields[0]);
    section.thickness = t;
  }
  // Elsets, materials and the one-section-per-element rule are checked when the deck is complete
  // (DeckReader::assign_sections), because Abaqus decks often define the material afterwards.
  model_.sections.push_back(std::move(section));
}

}  // namespace styk::inp
