// *SURFACE, *SURFACE INTERACTION, *SURFACE BEHAVIOR, *FRICTION, *CONTACT PAIR, *CLEARANCE and
// *CONTACT PRINT. Surfaces, interactions and orientations may be named before they are defined
// (Abaqus decks often define the interaction after the pair); resolve_contact_references()
// checks those names once the deck is complete and reports the line that used them.
#include <algorithm>
#include <cctype>
#include <utility>

#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {

namespace {

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

void sort_unique(std::vector<SurfaceFace>& faces) {
  const auto key = [](const SurfaceFace& f) { return std::make_pair(f.element, f.face); };
  std::sort(faces.begin(), faces.end(),
            [&](const SurfaceFace& x, const SurfaceFace& y) { return key(x) < key(y); });
  faces.erase(
      std::unique(faces.begin(), faces.end(),
                  [&](const SurfaceFace& x, const SurfaceFace& y) { return key(x) == key(y); }),
      faces.end());
}

// "S3" -> 3; 0 when the text is not S followed by a positive integer.
int face_number(const std::string& label) {
  if (label.size() < 2 || label.size() > 4 || label[0] != 'S') return 0;
  int face = 0;
  for (std::size_t i = 1; i < label.size(); ++i) {
    if (label[i] < '0' || label[i] > '9') return 0;
    face = face * 10 + (label[i] - '0');
  }
  return face;
}

// A coefficient of friction: a finite number >= 0.
double friction_field(const DataLine& line, std::size_t index, const std::string& what) {
  const double mu = real_field(line, index, what);
  if (mu < 0.0)
    throw InputError(line.where, what + " must not be negative, read " + line.fields[index]);
  return mu;
}

const char* const kContactVariables = "CSTR, CDIS, CSTATUS";

}  // namespace

void DeckReader::on_surface(const KeywordLine& kw) {
  Surface surface;
  surface.name = set_name(kw, "NAME");
  surface.where = kw.where;
  if (const auto existing = model_.surfaces.find(surface.name); existing != model_.surfaces.end())
    throw InputError(kw.where, "surface " + surface.name + " is defined twice (first at " +
                                   existing->second.where.str() + ")");
  if (const Parameter* type = kw.find("TYPE")) {
    const std::string value = normalize_name(type->value);
    if (value == "NODE")
      surface.kind = Surface::Kind::Nodes;
    else if (value != "ELEMENT")
      throw InputError(kw.where, "*SURFACE, TYPE=" + type->value +
                                     " is not supported; expected ELEMENT (element faces) or NODE");
  }
  while (std::optional<DataLine> line = next_data_line()) {
    if (surface.kind == Surface::Kind::Nodes) {
      for (std::size_t i = 0; i < line->fields.size(); ++i) {
        if (line->fields[i].empty()) continue;
        const std::vector<int> nodes = nodes_of(*line, i, "node or node set");
        surface.nodes.insert(surface.nodes.end(), nodes.begin(), nodes.end());
      }
      continue;
    }
    expect_fields(*line, 2, 2, "element or element set, face label S1..S6");
    const std::string label = normalize_name(line->fields[1]);
    const int face = face_number(label);
    if (face == 0)
      throw InputError(line->where, "face label " + quote(line->fields[1]) +
                                        " is not known; expected S1, S2, ... (the element type's "
                                        "faces, S1..S6 for a hexahedron)");
    for (int e : elements_of(*line, 0, "element or element set")) {
      const Element& element = model_.elements[e];
      const TElement* formulation = registry_.find(element.type);
      const int faces = formulation ? static_cast<int>(formulation->faces().size()) : 0;
      if (face > faces)
        throw InputError(line->where, "face label " + label + " is not a face of element " +
                                          std::to_string(element.id) + " (" + element.type +
                                          " has faces S1..S" + std::to_string(faces) + ")");
      surface.faces.push_back({e, face});
    }
  }
  sort_unique(surface.faces);
  sort_unique(surface.nodes);
  if (surface.faces.empty() && surface.nodes.empty())
    throw InputError(kw.where, "surface " + surface.name + " is empty: " + kw.label() +
                                   " needs data lines (element or element set, face label; or, "
                                   "with TYPE=NODE, nodes or node sets)");
  model_.surfaces.emplace(surface.name, std::move(surface));
}

void DeckReader::on_surface_interaction(const KeywordLine& kw) {
  const std::string name = normalize_name(kw.find("NAME")->value);
  if (const auto existing = model_.surface_interactions.find(name);
      existing != model_.surface_interactions.end())
    throw InputError(kw.where, "surface interaction " + name + " is defined twice (first at " +
                                   existing->second.where.str() + ")");
  SurfaceInteraction interaction;
  interaction.name = name;
  interaction.where = kw.where;
  model_.surface_interactions.emplace(name, std::move(interaction));
  interaction_ = name;
}

void DeckReader::on_surface_behavior(const KeywordLine& kw) {
  if (interaction_.empty())
    throw InputError(kw.where, kw.label() +
                                   " must follow *SURFACE INTERACTION (it belongs to the "
                                   "interaction defined just above it)");
  SurfaceInteraction& interaction = model_.surface_interactions.at(interaction_);
  if (interaction.behavior.where.line > 0)
    throw InputError(kw.where, "surface interaction " + interaction.name +
                                   " already has *SURFACE BEHAVIOR (at " +
                                   interaction.behavior.where.str() + ")");
  interaction.behavior = read_pressure_overclosure(kw);
}

namespace {

double positive_field(const DataLine& line, std::size_t index, const std::string& what) {
  const double value = real_field(line, index, what);
  if (!(value > 0.0))
    throw InputError(line.where, what + " must be positive, read " + line.fields[index]);
  return value;
}

bool field_given(const DataLine& line, std::size_t index) {
  return line.fields.size() > index && !line.fields[index].empty();
}

}  // namespace

// CalculiX's data lines: LINEAR "K, sigma_inf, c0" (sigma_inf and c0 only for node-to-face
// contact, c0 defaulting to 1e-3), EXPONENTIAL "c0, p0", TIED "K"; HARD none.
PressureOverclosure DeckReader::read_pressure_overclosure(const KeywordLine& kw) {
  using Law = PressureOverclosure::Law;
  PressureOverclosure behavior;
  behavior.where = kw.where;
  const std::string law = normalize_name(kw.find("PRESSURE-OVERCLOSURE")->value);
  if (law == "HARD") {
    if (std::optional<DataLine> line = next_data_line())
      throw InputError(line->where,
                       "PRESSURE-OVERCLOSURE=HARD takes no data line (Styk enforces hard contact "
                       "exactly); penalty parameters belong to LINEAR, EXPONENTIAL or TIED");
    return behavior;
  }
  if (law == "LINEAR") {
    behavior.law = Law::Linear;
    const std::optional<DataLine> line = single_data_line(kw, true, "K [, sigma_inf [, c0]]");
    expect_fields(*line, 1, 3, "K [, sigma_inf [, c0]]");
    behavior.slope = positive_field(*line, 0, "the slope K of the pressure-overclosure curve");
    if (field_given(*line, 1)) {
      const double sigma = real_field(*line, 1, "sigma_inf (tension at large clearances)");
      if (sigma < 0.0)
        throw InputError(line->where,
                         "sigma_inf (tension at large clearances) must not be "
                         "negative, read " +
                             line->fields[1]);
      behavior.sigma_inf = sigma;
    }
    if (field_given(*line, 2)) behavior.c0 = positive_field(*line, 2, "c0 (clearance factor)");
    return behavior;
  }
  if (law == "EXPONENTIAL") {
    behavior.law = Law::Exponential;
    const std::optional<DataLine> line = single_data_line(kw, true, "c0, p0");
    expect_fields(*line, 2, 2, "c0, p0");
    behavior.c0 = positive_field(*line, 0, "c0 (clearance at which the pressure is 1 % of p0)");
    behavior.p0 = positive_field(*line, 1, "p0 (contact pressure at zero clearance)");
    return behavior;
  }
  if (law == "TIED") {
    behavior.law = Law::Tied;
    const std::optional<DataLine> line = single_data_line(kw, true, "K");
    expect_fields(*line, 1, 1, "K");
    behavior.slope = positive_field(*line, 0, "the slope K of the pressure-overclosure curve");
    return behavior;
  }
  throw InputError(kw.where, "PRESSURE-OVERCLOSURE=" + kw.find("PRESSURE-OVERCLOSURE")->value +
                                 " is not supported; expected HARD (exact contact, the "
                                 "default), LINEAR, EXPONENTIAL or TIED" +
                                 (law == "TABULAR" ? " (TABULAR pressure-overclosure tables are "
                                                     "not supported)"
                                                   : ""));
}

void DeckReader::on_friction(const KeywordLine& kw) {
  if (interaction_.empty())
    throw InputError(kw.where, kw.label() +
                                   " must follow *SURFACE INTERACTION (it belongs to the "
                                   "interaction defined just above it)");
  SurfaceInteraction& interaction = model_.surface_interactions.at(interaction_);
  if (interaction.friction)
    throw InputError(kw.where, "surface interaction " + interaction.name +
                                   " already has *FRICTION (at " +
                                   interaction.friction->where.str() + ")");
  Friction friction;
  friction.where = kw.where;
  const bool rough = kw.find("ROUGH") != nullptr;
  const bool anisotropic = kw.find("ANISOTROPIC") != nullptr;
  if (rough && anisotropic)
    throw InputError(kw.where, "*FRICTION: ROUGH (no slip) and ANISOTROPIC exclude each other");
  if (const Parameter* orientation = kw.find("ORIENTATION")) {
    if (!anisotropic)
      throw InputError(kw.where,
                       "*FRICTION: ORIENTATION= gives the slip directions of "
                       "ANISOTROPIC friction; add ANISOTROPIC or remove ORIENTATION=");
    friction.orientation = normalize_name(orientation->value);
  }
  if (rough) {
    friction.kind = Friction::Kind::Rough;
    if (std::optional<DataLine> line = next_data_line())
      throw InputError(line->where,
                       "*FRICTION, ROUGH means no slip at all: it takes no friction "
                       "coefficient (remove the data line or ROUGH)");
    interaction.friction = friction;
    return;
  }
  if (anisotropic) {
    friction.kind = Friction::Kind::Anisotropic;
    if (friction.orientation.empty())
      throw InputError(kw.where,
                       "*FRICTION, ANISOTROPIC needs ORIENTATION=name: the *ORIENTATION "
                       "whose local directions 1 and 2 carry mu1 and mu2");
    const std::optional<DataLine> line = single_data_line(kw, true, "mu1, mu2");
    expect_fields(*line, 2, 2, "mu1, mu2 (dependence on slip rate or pressure is not supported)");
    friction.mu = friction_field(*line, 0, "friction coefficient mu1");
    friction.mu2 = friction_field(*line, 1, "friction coefficient mu2");
  } else {
    const std::optional<DataLine> line = single_data_line(kw, true, "mu [, stick slope]");
    expect_fields(*line, 1, 2, "mu [, stick slope]");
    friction.mu = friction_field(*line, 0, "friction coefficient mu");
    if (line->fields.size() > 1 && !line->fields[1].empty()) {
      const double slope = real_field(*line, 1, "stick slope");
      if (slope <= 0.0)
        throw InputError(line->where, "stick slope must be positive, read " + line->fields[1]);
      friction.stick_slope = slope;
    }
  }
  interaction.friction = friction;
}

void DeckReader::on_contact_pair(const KeywordLine& kw) {
  ContactPair pair;
  pair.where = kw.where;
  pair.interaction = normalize_name(kw.find("INTERACTION")->value);
  if (const Parameter* type = kw.find("TYPE")) {
    const std::string value = normalize_name(type->value);
    if (value == "SURFACE TO SURFACE")
      pair.type = ContactPair::Type::SurfaceToSurface;
    else if (value == "MORTAR")
      pair.type = ContactPair::Type::Mortar;
    else if (value != "NODE TO SURFACE")
      throw InputError(kw.where, "*CONTACT PAIR, TYPE=" + type->value +
                                     " is not supported; expected NODE TO SURFACE, SURFACE TO "
                                     "SURFACE or MORTAR");
  }
  if (const Parameter* adjust = kw.find("ADJUST")) {
    if (!names_a_set(adjust->value)) {
      const double tolerance = real_value(adjust->value, "ADJUST= of *CONTACT PAIR", kw.where);
      if (tolerance < 0.0)
        throw InputError(kw.where,
                         "ADJUST=" + adjust->value + ": the adjust tolerance must not be negative");
      pair.adjust_tolerance = tolerance;
    } else {
      pair.adjust_nset = set_name(kw, "ADJUST");
      if (!model_.find_nset(pair.adjust_nset))
        throw InputError(kw.where, "ADJUST=" + pair.adjust_nset +
                                       " of *CONTACT PAIR: node set is not defined; node sets: " +
                                       some_names(model_.nsets));
    }
  }
  bool any = false;
  while (std::optional<DataLine> line = next_data_line()) {
    expect_fields(*line, 2, 2, "slave surface, master surface");
    ContactPair one = pair;
    one.where = line->where;
    one.slave = normalize_name(line->fields[0]);
    one.master = normalize_name(line->fields[1]);
    if (one.slave.empty() || one.master.empty())
      throw InputError(line->where, "*CONTACT PAIR data line needs a slave and a master surface");
    if (one.slave == one.master)
      throw InputError(line->where, "surface " + one.slave +
                                        " is both slave and master; self-contact is not supported");
    model_.contact_pairs.push_back(std::move(one));
    any = true;
  }
  if (!any)
    throw InputError(kw.where, kw.label() + " needs a data line: slave surface, master surface");
}

void DeckReader::on_clearance(const KeywordLine& kw) {
  PendingClearance clearance;
  clearance.slave = normalize_name(kw.find("SLAVE")->value);
  clearance.master = normalize_name(kw.find("MASTER")->value);
  clearance.value = real_value(kw.find("VALUE")->value, "VALUE= of *CLEARANCE", kw.where);
  clearance.where = kw.where;
  clearances_.push_back(std::move(clearance));
}

void DeckReader::on_contact_print(const KeywordLine& kw) {
  OutputRequest request;
  request.kind = OutputRequest::Kind::ContactPrint;
  request.where = kw.where;
  while (std::optional<DataLine> line = next_data_line()) {
    for (const std::string& field : line->fields) {
      if (field.empty()) continue;
      const std::string var = normalize_name(field);
      if (var != "CSTR" && var != "CDIS" && var != "CSTATUS")
        throw InputError(line->where,
                         "output variable " + quote(field) + " is not supported by " + kw.label() +
                             "; Styk writes " + kContactVariables +
                             (var == "CELS" ? " (Styk does not write the contact elastic "
                                              "energy)"
                                            : ""));
      if (std::find(request.vars.begin(), request.vars.end(), var) == request.vars.end())
        request.vars.push_back(var);
    }
  }
  if (request.vars.empty())
    throw InputError(kw.where, kw.label() + " needs a data line naming the variables (" +
                                   kContactVariables + ")");
  current_step().outputs.push_back(std::move(request));
}

void DeckReader::resolve_contact_references() {
  for (const auto& entry : model_.surface_interactions) {
    const SurfaceInteraction& interaction = entry.second;
    if (!interaction.friction || interaction.friction->orientation.empty()) continue;
    if (!model_.orientations.count(interaction.friction->orientation))
      throw InputError(
          interaction.friction->where,
          "ORIENTATION=" + interaction.friction->orientation +
              " of *FRICTION is not defined; orientations: " + some_names(model_.orientations));
  }
  for (const ContactPair& pair : model_.contact_pairs) {
    for (const std::string* name : {&pair.slave, &pair.master}) {
      if (!model_.surfaces.count(*name))
        throw InputError(pair.where,
                         "*CONTACT PAIR names surface " + *name +
                             ", which is not defined; surfaces: " + some_names(model_.surfaces));
    }
    if (model_.surfaces.at(pair.master).kind != Surface::Kind::ElementFaces)
      throw InputError(pair.where, "master surface " + pair.master +
                                       " is a node surface (TYPE=NODE); a master surface must "
                                       "consist of element faces");
    if (pair.type != ContactPair::Type::NodeToSurface &&
        model_.surfaces.at(pair.slave).kind != Surface::Kind::ElementFaces)
      throw InputError(
          pair.where,
          "slave surface " + pair.slave + " is a node surface; TYPE=" +
              (pair.type == ContactPair::Type::Mortar ? "MORTAR" : "SURFACE TO SURFACE") +
              " needs element faces on both sides (or use TYPE=NODE TO SURFACE)");
    if (!model_.surface_interactions.count(pair.interaction))
      throw InputError(pair.where, "INTERACTION=" + pair.interaction +
                                       " of *CONTACT PAIR is not defined; surface interactions: " +
                                       some_names(model_.surface_interactions));
  }
  for (const PendingClearance& clearance : clearances_) {
    const auto pair = std::find_if(
        model_.contact_pairs.begin(), model_.contact_pairs.end(), [&](const ContactPair& p) {
          return p.slave == clearance.slave && p.master == clearance.master;
        });
    if (pair == model_.contact_pairs.end()) {
      std::string pairs;
      for (const ContactPair& p : model_.contact_pairs)
        pairs += (pairs.empty() ? "" : "; ") + p.slave + ", " + p.master;
      throw InputError(clearance.where,
                       "*CLEARANCE names the pair SLAVE=" + clearance.slave +
                           ", MASTER=" + clearance.master + ", but no *CONTACT PAIR has them; " +
                           (pairs.empty() ? "no contact pairs are defined" : "pairs: " + pairs));
    }
    if (pair->clearance)
      throw InputError(clearance.where, "the pair " + pair->slave + ", " + pair->master +
                                            " already has a *CLEARANCE (at " +
                                            pair->clearance_where.str() + ")");
    pair->clearance = clearance.value;
    pair->clearance_where = clearance.where;
  }
}

}  // namespace styk::inp
