// Loads and initial states beyond nodal forces and face pressures: *DLOAD GRAV and CENTRIF (body
// forces), *DSLOAD (pressure on a surface), *INITIAL CONDITIONS, TYPE=STRESS and *CHANGE SOLID
// SECTION.
#include <cmath>

#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {

namespace {

// The unit vector of fields first..first+2, named `what` in messages.
Vec3 unit_vector(const DataLine& line, std::size_t first, const std::string& what) {
  Vec3 v{};
  for (std::size_t i = 0; i < 3; ++i)
    v[i] = real_field(line, first + i, what + " component " + std::to_string(i + 1));
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(length > 0.0)) throw InputError(line.where, what + " is the zero vector");
  for (double& c : v) c /= length;
  return v;
}

}  // namespace

void DeckReader::read_body_load(const DataLine& line, const std::string& label) {
  Step& step = current_step();
  BodyLoad load;
  load.where = line.where;
  if (label == "GRAV") {
    // elset, GRAV, magnitude, direction (x, y, z): acceleration magnitude along the direction.
    expect_fields(line, 6, 6, "element or element set, GRAV, magnitude, direction x, y, z");
    load.kind = BodyLoad::Kind::Gravity;
    load.magnitude = real_field(line, 2, "gravity magnitude");
    load.direction = unit_vector(line, 3, "gravity direction");
  } else {
    // elset, CENTRIF, omega^2, point on the axis (x, y, z), axis direction (x, y, z).
    expect_fields(line, 9, 9,
                  "element or element set, CENTRIF, omega^2, axis point x, y, z, axis direction "
                  "x, y, z");
    load.kind = BodyLoad::Kind::Centrifugal;
    load.magnitude = real_field(line, 2, "omega^2 (rotational speed squared)");
    if (load.magnitude < 0.0)
      throw InputError(line.where, "CENTRIF: omega^2 must not be negative, read " + line.fields[2]);
    for (std::size_t i = 0; i < 3; ++i)
      load.point[i] = real_field(line, 3 + i, "axis point component " + std::to_string(i + 1));
    load.direction = unit_vector(line, 6, "axis direction");
  }
  for (int e : elements_of(line, 0, "element or element set")) {
    load.element = e;
    step.body_loads.push_back(load);
  }
}

void DeckReader::on_dsload(const KeywordLine& kw) {
  Step& step = current_step();
  if (const Parameter* op = kw.find("OP")) {
    const std::string value = normalize_name(op->value);
    if (value == "NEW")
      step.dload_op_new = true;
    else if (value != "MOD")
      throw InputError(kw.where, "OP=" + op->value + " on *DSLOAD: expected NEW or MOD");
  }
  bool any = false;
  while (std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 3, 3, "element-face surface, P, magnitude");
    const std::string label = normalize_name(line->fields[1]);
    if (label != "P")
      throw InputError(line->where, "*DSLOAD load label " + quote(line->fields[1]) +
                                        " is not supported; Styk reads P (uniform pressure)");
    const std::string name = normalize_name(line->fields[0]);
    const auto surface = model_.surfaces.find(name);
    if (surface == model_.surfaces.end())
      throw InputError(line->where, "*DSLOAD: surface " + name +
                                        " is not defined (surfaces must be defined above the "
                                        "step); surfaces: " +
                                        some_names(model_.surfaces));
    if (surface->second.kind != Surface::Kind::ElementFaces)
      throw InputError(line->where, "*DSLOAD: surface " + name +
                                        " is a node surface; a pressure needs element faces");
    const double magnitude = real_field(*line, 2, "pressure");
    // A pressure on each face, as *DLOAD, Pn would give it.
    for (const SurfaceFace& face : surface->second.faces)
      step.dloads.push_back({face.element, face.face, magnitude, line->where});
    any = true;
  }
  if (!any) throw InputError(kw.where, "*DSLOAD needs data lines: surface, P, magnitude");
}

void DeckReader::read_initial_stresses(const KeywordLine& kw) {
  if (kw.find("USER"))
    throw InputError(kw.where,
                     "*INITIAL CONDITIONS, TYPE=STRESS, USER needs a user subroutine "
                     "(SIGINI), which Styk does not run; give the stresses on data "
                     "lines");
  std::map<std::pair<int, int>, InitialStress> stresses;
  for (const InitialStress& s : model_.initial_stresses) stresses[{s.element, s.point}] = s;
  bool any = false;
  while (std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 8, 8, "element, integration point, s11, s22, s33, s12, s13, s23");
    const std::int64_t point = integer_field(*line, 1, "integration point");
    if (point < 1)
      throw InputError(line->where,
                       "integration points are numbered from 1, read " + line->fields[1]);
    InitialStress s;
    s.point = static_cast<int>(point);
    s.where = line->where;
    for (std::size_t c = 0; c < 6; ++c)
      s.stress[c] = real_field(*line, 2 + c, "stress component " + std::to_string(c + 1));
    // Whether the point exists in the element's rule is checked by the solver, which knows it.
    for (int e : elements_of(*line, 0, "element or element set")) {
      s.element = e;
      stresses[{e, s.point}] = s;  // a later line for the same point replaces an earlier one
    }
    any = true;
  }
  if (!any)
    throw InputError(kw.where, kw.label() +
                                   ", TYPE=STRESS needs data lines: element, "
                                   "integration point, s11, s22, s33, s12, s13, s23");
  model_.initial_stresses.clear();
  for (const auto& entry : stresses) model_.initial_stresses.push_back(entry.second);
}

void DeckReader::on_change_solid_section(const KeywordLine& kw) {
  SectionChange change;
  change.elset = set_name(kw, "ELSET");
  change.material = normalize_name(kw.find("MATERIAL")->value);
  change.where = kw.where;
  if (!model_.find_elset(change.elset))
    throw InputError(kw.where, "*CHANGE SOLID SECTION: element set " + change.elset +
                                   " is not defined; element sets: " + some_names(model_.elsets));
  change.material_index = model_.material_index(change.material);
  if (change.material_index < 0) {
    std::string names;
    for (const Material& m : model_.materials) names += (names.empty() ? "" : ", ") + m.name;
    throw InputError(kw.where, "*CHANGE SOLID SECTION: material " + change.material +
                                   " is not defined; materials: " +
                                   (names.empty() ? "none are defined" : names));
  }
  if (std::optional<DataLine> line = next_data_line())
    throw InputError(line->where,
                     "*CHANGE SOLID SECTION takes no data lines (it changes the "
                     "material only)");
  current_step().section_changes.push_back(std::move(change));
}

}  // namespace styk::inp
