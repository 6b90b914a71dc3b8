// *MATERIAL, *DENSITY, *SOLID SECTION (*ELASTIC and *EXPANSION: material_keywords.cpp).
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

void DeckReader::on_density(const KeywordLine& kw) {
  Material& m = current_material(kw);
  const std::optional<DataLine> line = single_data_line(kw, true, "density");
  expect_fields(*line, 1, 1, "density (temperature-dependent data is not supported)");
  const double rho = real_field(*line, 0, "density");
  if (rho <= 0.0)
    throw InputError(line->where, "density must be positive, read " + line->fields[0]);
  m.density = rho;
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
  // The material axes: an *ORIENTATION, which may be defined later (checked in assign_sections).
  if (const Parameter* orientation = kw.find("ORIENTATION"))
    section.orientation = normalize_name(orientation->value);
  // CalculiX: OFFSET moves the mid-plane of a plane element's 3D expansion; 0 is the default, and
  // Styk's plane elements are not expanded, so only 0 means what the deck says.
  if (const Parameter* offset = kw.find("OFFSET");
      offset && real_value(offset->value, "OFFSET=", kw.where) != 0.0)
    throw InputError(kw.where, "OFFSET=" + offset->value +
                                   " on *SOLID SECTION is not supported; Styk reads OFFSET=0 "
                                   "(plane elements are not expanded into 3D)");
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
