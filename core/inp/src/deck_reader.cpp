#include "deck_reader.hpp"

#include <algorithm>

#include "numbers.hpp"

namespace styk::inp {

namespace {
constexpr bool kData = true;
constexpr bool kNoData = false;
}  // namespace

const std::vector<DeckReader::KeywordSpec>& DeckReader::keywords() {
  using S = Scope;
  using V = Value;
  static const std::vector<KeywordSpec> table = {
      {"HEADING", S::Model, {}, &DeckReader::on_heading, kData},
      {"NODE", S::Model, {{"NSET", false, V::Required}}, &DeckReader::on_node, kData},
      {"ELEMENT",
       S::Model,
       {{"TYPE", true, V::Required}, {"ELSET", false, V::Required}},
       &DeckReader::on_element,
       kData},
      {"NSET",
       S::Model,
       {{"NSET", true, V::Required}, {"GENERATE", false, V::None}},
       &DeckReader::on_nset,
       kData},
      {"ELSET",
       S::Model,
       {{"ELSET", true, V::Required}, {"GENERATE", false, V::None}},
       &DeckReader::on_elset,
       kData},
      {"MATERIAL", S::Model, {{"NAME", true, V::Required}}, &DeckReader::on_material, kNoData},
      {"ELASTIC", S::Material, {{"TYPE", false, V::Required}}, &DeckReader::on_elastic, kData},
      {"DENSITY", S::Material, {}, &DeckReader::on_density, kData},
      {"EXPANSION",
       S::Material,
       {{"ZERO", false, V::Required}, {"TYPE", false, V::Required}},
       &DeckReader::on_expansion,
       kData},
      {"SOLID SECTION",
       S::Model,
       {{"ELSET", true, V::Required},
        {"MATERIAL", true, V::Required},
        {"TECHNIQUE", false, V::Required},  // Styk-only (B-bar)
        {"ORIENTATION", false, V::Required},
        {"OFFSET", false, V::Required}},  // CalculiX; 0 only
       &DeckReader::on_solid_section,
       kData},
      {"BEAM SECTION",
       S::Model,
       {{"ELSET", true, V::Required},
        {"MATERIAL", true, V::Required},
        {"SECTION", true, V::Required},
        {"INTEGRATION", false, V::Required},  // Styk-only (REDUCED | FULL)
        {"OFFSET1", false, V::Required},      // CalculiX; only 0 is accepted
        {"OFFSET2", false, V::Required},
        {"ORIENTATION", false, V::Required},  // CalculiX; refused by name
        {"NODAL THICKNESS", false, V::None}},
       &DeckReader::on_beam_section,
       kData},
      {"SHELL SECTION",
       S::Model,
       {{"ELSET", true, V::Required},
        {"MATERIAL", true, V::Required},
        {"OFFSET", false, V::Required},
        {"ORIENTATION", false, V::Required},  // CalculiX; refused by name
        {"COMPOSITE", false, V::None},
        {"NODAL THICKNESS", false, V::None}},
       &DeckReader::on_shell_section,
       kData},
      {"NORMAL", S::Model, {{"TYPE", false, V::Required}}, &DeckReader::on_normal, kData},
      {"BOUNDARY",
       S::Anywhere,
       {{"OP", false, V::Required}, {"FIXED", false, V::None}},
       &DeckReader::on_boundary,
       kData},
      {"STEP",
       S::Model,
       {{"NAME", false, V::Required}, {"NLGEOM", false, V::Optional}, {"INC", false, V::Required}},
       &DeckReader::on_step,
       kNoData},
      {"STATIC",
       S::Step,
       {{"SOLVER", false, V::Required}, {"DIRECT", false, V::None}},
       &DeckReader::on_static,
       kData},
      {"CLOAD", S::Step, {{"OP", false, V::Required}}, &DeckReader::on_cload, kData},
      {"DLOAD", S::Step, {{"OP", false, V::Required}}, &DeckReader::on_dload, kData},
      // Surface loads and state changes of a step (load_keywords.cpp)
      {"DSLOAD", S::Step, {{"OP", false, V::Required}}, &DeckReader::on_dsload, kData},
      {"CHANGE SOLID SECTION",
       S::Step,
       {{"ELSET", true, V::Required}, {"MATERIAL", true, V::Required}},
       &DeckReader::on_change_solid_section,
       kData},
      {"NODE PRINT",
       S::Step,
       {{"NSET", false, V::Required},
        {"TOTALS", false, V::Required},
        {"GLOBAL", false, V::Required},
        {"FREQUENCY", false, V::Required}},
       &DeckReader::on_node_print,
       kData},
      {"EL PRINT",
       S::Step,
       {{"ELSET", false, V::Required},
        {"POSITION", false, V::Required},
        {"TOTALS", false, V::Required},
        {"GLOBAL", false, V::Required},
        {"FREQUENCY", false, V::Required}},
       &DeckReader::on_el_print,
       kData},
      {"NODE FILE",
       S::Step,
       {{"NSET", false, V::Required},
        {"GLOBAL", false, V::Required},
        {"FREQUENCY", false, V::Required},
        {"OUTPUT", false, V::Required}},
       &DeckReader::on_node_file,
       kData},
      {"EL FILE",
       S::Step,
       {{"ELSET", false, V::Required},
        {"GLOBAL", false, V::Required},
        {"FREQUENCY", false, V::Required},
        {"OUTPUT", false, V::Required},
        // CalculiX: beams' section forces in the .frd instead of their stresses; Styk's results
        // hold both for every beam and shell (SF, SM), so the request is always met.
        {"SECTION FORCES", false, V::None}},
       &DeckReader::on_el_file,
       kData},
      {"SECTION PRINT",
       S::Step,
       {{"SURFACE", true, V::Required},
        {"NAME", true, V::Required},
        {"FREQUENCYF", false, V::Required},
        {"FREQUENCY", false, V::Required}},
       &DeckReader::on_section_print,
       kData},
      {"END STEP", S::Step, {}, &DeckReader::on_end_step, kNoData},
      // Contact (contact_keywords.cpp)
      {"SURFACE",
       S::Model,
       {{"NAME", true, V::Required}, {"TYPE", false, V::Required}},
       &DeckReader::on_surface,
       kData},
      {"SURFACE INTERACTION",
       S::Model,
       {{"NAME", true, V::Required}},
       &DeckReader::on_surface_interaction,
       kNoData},
      {"SURFACE BEHAVIOR",
       S::Interaction,
       {{"PRESSURE-OVERCLOSURE", true, V::Required}},
       &DeckReader::on_surface_behavior,
       kData},
      {"FRICTION",
       S::Interaction,
       {{"ANISOTROPIC", false, V::None},
        {"ROUGH", false, V::None},
        {"ORIENTATION", false, V::Required}},
       &DeckReader::on_friction,
       kData},
      {"CONTACT PAIR",
       S::Model,
       {{"INTERACTION", true, V::Required},
        {"TYPE", false, V::Required},
        {"ADJUST", false, V::Required}},
       &DeckReader::on_contact_pair,
       kData},
      {"CLEARANCE",
       S::Model,
       {{"SLAVE", true, V::Required}, {"MASTER", true, V::Required}, {"VALUE", true, V::Required}},
       &DeckReader::on_clearance,
       kNoData},
      {"CONTACT PRINT", S::Step, {}, &DeckReader::on_contact_print, kData},
      // Local systems and constraints (constraint_keywords.cpp)
      {"ORIENTATION",
       S::Model,
       {{"NAME", true, V::Required},
        {"SYSTEM", false, V::Required},
        {"DEFINITION", false, V::Required}},
       &DeckReader::on_orientation,
       kData},
      {"TRANSFORM",
       S::Model,
       {{"NSET", true, V::Required}, {"TYPE", false, V::Required}},
       &DeckReader::on_transform,
       kData},
      {"EQUATION", S::Model, {}, &DeckReader::on_equation, kData},
      // Ties (tie_keywords.cpp; CYCLIC SYMMETRY: cyclic_keywords.cpp), couplings, MPCs and
      // pre-tension (coupling_keywords.cpp)
      {"TIE",
       S::Model,
       {{"NAME", true, V::Required},
        {"POSITION TOLERANCE", false, V::Required},
        {"ADJUST", false, V::Required},
        {"CYCLIC SYMMETRY", false, V::None},
        {"MULTISTAGE", false, V::None},
        {"FLUID PERIODIC", false, V::None},
        {"FLUID CYCLIC", false, V::None}},
       &DeckReader::on_tie,
       kData},
      {"COUPLING",
       S::Model,
       {{"REF NODE", true, V::Required},
        {"SURFACE", true, V::Required},
        {"CONSTRAINT NAME", true, V::Required},
        {"ORIENTATION", false, V::Required}},
       &DeckReader::on_coupling,
       kNoData},
      {"KINEMATIC", S::Model, {}, &DeckReader::on_coupling_kind, kData},
      {"DISTRIBUTING", S::Model, {}, &DeckReader::on_coupling_kind, kData},
      {"MPC", S::Model, {}, &DeckReader::on_mpc, kData},
      {"PRE-TENSION SECTION",
       S::Model,
       {{"SURFACE", false, V::Required},
        {"NODE", true, V::Required},
        {"ELEMENT", false, V::Required}},
       &DeckReader::on_pretension_section,
       kData},
      {"CYCLIC SYMMETRY MODEL",
       S::Model,
       {{"N", true, V::Required},
        {"NGRAPH", false, V::Required},
        {"TIE", false, V::Required},
        {"CHECK", false, V::Required}},
       &DeckReader::on_cyclic_symmetry_model,
       kData},
      // Pressure penetration (penetration_keywords.cpp; Styk extension after Abaqus)
      {"PRESSURE PENETRATION",
       S::Step,
       {{"SLAVE", true, V::Required},
        {"MASTER", true, V::Required},
        {"OP", false, V::Required},
        {"LEAK", false, V::Required}},
       &DeckReader::on_pressure_penetration,
       kData},
      // Temperatures (thermal_keywords.cpp)
      {"INITIAL CONDITIONS",
       S::Model,
       {{"TYPE", true, V::Required}, {"USER", false, V::None}},
       &DeckReader::on_initial_conditions,
       kData},
      {"TEMPERATURE", S::Step, {{"OP", false, V::Required}}, &DeckReader::on_temperature, kData},
      // Steady heat and electric potential (scalar_keywords.cpp)
      {"HEAT TRANSFER",
       S::Step,
       {{"STEADY STATE", false, V::None}},
       &DeckReader::on_heat_transfer,
       kData},
      {"COUPLED THERMAL-ELECTRICAL",
       S::Step,
       {{"STEADY STATE", false, V::None}},
       &DeckReader::on_coupled_thermal_electrical,
       kData},
      {"CONDUCTIVITY",
       S::Material,
       {{"TYPE", false, V::Required}},
       &DeckReader::on_conductivity,
       kData},
      {"ELECTRICAL CONDUCTIVITY",
       S::Material,
       {{"TYPE", false, V::Required}},
       &DeckReader::on_conductivity,
       kData},
      {"CFLUX", S::Step, {{"OP", false, V::Required}}, &DeckReader::on_cflux, kData},
      {"CECUR", S::Step, {{"OP", false, V::Required}}, &DeckReader::on_cecur, kData},
      {"DFLUX", S::Step, {{"OP", false, V::Required}}, &DeckReader::on_dflux, kData},
  };
  return table;
}

DeckReader::DeckReader(const std::string& path, const ElementRegistry& registry,
                       DeckCompleteness completeness)
    : source_(path), registry_(registry), completeness_(completeness) {
  model_.source = path;
}

Model DeckReader::read() {
  while (std::optional<Card> card = source_.next()) {
    if (!card->is_keyword) {
      if (last_keyword_.empty())
        throw InputError(card->where, "data line " + quote(card->text) +
                                          " before the first keyword (keyword lines start with "
                                          "'*', comments with '**')");
      throw InputError(card->where, "unexpected data line " + quote(card->text) + ": *" +
                                        last_keyword_ + " takes no data lines");
    }
    dispatch(parse_keyword_line(card->text, card->where));
  }
  finish();
  return std::move(model_);
}

void DeckReader::dispatch(const KeywordLine& kw) {
  const std::vector<KeywordSpec>& table = keywords();
  const auto spec = std::find_if(table.begin(), table.end(),
                                 [&](const KeywordSpec& s) { return kw.name == s.name; });
  if (spec == table.end()) {
    std::string known;
    for (const KeywordSpec& s : table) known += std::string(known.empty() ? "*" : ", *") + s.name;
    throw InputError(kw.where, "unknown keyword " + kw.label() + " (Styk reads " + known +
                                   ", *INCLUDE; see docs/input.md)");
  }
  if (spec->scope != Scope::Material) material_ = -1;
  if (kw.name != "KINEMATIC" && kw.name != "DISTRIBUTING" && coupling_open_)
    throw InputError(kw.where, "*COUPLING " + model_.couplings.back().name + " (at " +
                                   model_.couplings.back().where.str() +
                                   ") must be followed directly by *KINEMATIC or *DISTRIBUTING");
  if (spec->scope != Scope::Interaction) interaction_.clear();
  switch (spec->scope) {
    case Scope::Model:
      if (in_step_)
        throw InputError(kw.where,
                         kw.label() + " is not allowed inside a step (the step starts at " +
                             current_step().where.str() +
                             (kw.name == "STEP" ? " and has no *END STEP)"
                                                : "); model data goes before the first *STEP"));
      break;
    case Scope::Material:
    case Scope::Interaction:
      if (in_step_) throw InputError(kw.where, kw.label() + " is not allowed inside a step");
      break;
    case Scope::Step:
      if (!in_step_)
        throw InputError(kw.where,
                         kw.label() + " is only allowed inside a step (*STEP ... *END STEP)");
      break;
    case Scope::Anywhere:
      break;
  }
  check_parameters(*spec, kw);
  last_keyword_ = kw.name;
  (this->*(spec->handler))(kw);
}

void DeckReader::check_parameters(const KeywordSpec& spec, const KeywordLine& kw) const {
  for (const Parameter& p : kw.params) {
    const auto ps = std::find_if(spec.params.begin(), spec.params.end(),
                                 [&](const ParamSpec& s) { return p.name == s.name; });
    if (ps == spec.params.end()) {
      std::string accepted;
      for (const ParamSpec& s : spec.params)
        accepted += std::string(accepted.empty() ? "" : ", ") + s.name +
                    (s.value == Value::Required ? "=" : "");
      throw InputError(kw.where, "unknown parameter " + p.name + " on " + kw.label() +
                                     (accepted.empty() ? " (it takes no parameters)"
                                                       : " (accepted: " + accepted + ")"));
    }
    if (ps->value == Value::Required && (!p.has_value || p.value.empty()))
      throw InputError(kw.where, "parameter " + p.name + " of " + kw.label() + " needs a value (" +
                                     p.name + "=...)");
    if (ps->value == Value::None && p.has_value)
      throw InputError(kw.where, "parameter " + p.name + " of " + kw.label() +
                                     " takes no value (read " + p.name + "=" + p.value + ")");
  }
  for (const ParamSpec& s : spec.params)
    if (s.required && !kw.find(s.name))
      throw InputError(kw.where, kw.label() + " needs " + s.name + "=");
}

std::optional<DataLine> DeckReader::next_data_line() {
  const Card* card = source_.peek();
  if (!card || card->is_keyword) return std::nullopt;
  std::optional<Card> taken = source_.next();
  return split_data_line(taken->text, taken->where);
}

void DeckReader::expect_fields(const DataLine& line, std::size_t min, std::size_t max,
                               const std::string& layout) const {
  const std::size_t n = line.fields.size();
  if (n >= min && n <= max) return;
  throw InputError(line.where, "*" + last_keyword_ + " data line has " + std::to_string(n) +
                                   " field" + (n == 1 ? "" : "s") + ", expected " + layout);
}

std::optional<DataLine> DeckReader::single_data_line(const KeywordLine& kw, bool required,
                                                     const std::string& layout) {
  std::optional<DataLine> line = next_data_line();
  if (!line && required) throw InputError(kw.where, kw.label() + " needs a data line: " + layout);
  if (line) {
    if (std::optional<DataLine> extra = next_data_line())
      throw InputError(extra->where, kw.label() + " takes one data line (" + layout +
                                         "); temperature-dependent or repeated data is not "
                                         "supported");
  }
  return line;
}

std::string DeckReader::set_name(const KeywordLine& kw, const char* param) const {
  const Parameter* p = kw.find(param);
  const std::string name = normalize_name(p->value);
  // A data field that reads as a number is an id, so such a name could never be referred to.
  if (!names_a_set(name) || name.find(' ') != std::string::npos)
    throw InputError(kw.where, std::string(param) + "=" + p->value +
                                   ": a set name has no blanks and does not read as a number "
                                   "(a data field that does is an id)");
  return name;
}

int DeckReader::node_by_id(Id id, const SourceLoc& where, const std::string& context) const {
  const int index = model_.node_index(id);
  if (index < 0)
    throw InputError(where, context + ": node " + std::to_string(id) +
                                " is not defined (nodes must be defined by *NODE before they "
                                "are used)");
  return index;
}

int DeckReader::element_by_id(Id id, const SourceLoc& where, const std::string& context) const {
  const int index = model_.element_index(id);
  if (index < 0)
    throw InputError(where, context + ": element " + std::to_string(id) +
                                " is not defined (elements must be defined by *ELEMENT before "
                                "they are used)");
  return index;
}

std::vector<int> DeckReader::nodes_of(const DataLine& line, std::size_t field,
                                      const std::string& what) {
  const std::string& text = field < line.fields.size() ? line.fields[field] : std::string();
  if (!names_a_set(text))
    return {
        node_by_id(id_field(line, field, what), line.where, "field " + std::to_string(field + 1))};
  const NodeSet* set = model_.find_nset(text);
  if (!set)
    throw InputError(line.where, "field " + std::to_string(field + 1) + " (" + what +
                                     "): node set " + normalize_name(text) +
                                     " is not defined; node sets: " + some_names(model_.nsets));
  return set->nodes;
}

std::vector<int> DeckReader::elements_of(const DataLine& line, std::size_t field,
                                         const std::string& what) {
  const std::string& text = field < line.fields.size() ? line.fields[field] : std::string();
  if (!names_a_set(text))
    return {element_by_id(id_field(line, field, what), line.where,
                          "field " + std::to_string(field + 1))};
  const ElementSet* set = model_.find_elset(text);
  if (!set)
    throw InputError(line.where, "field " + std::to_string(field + 1) + " (" + what +
                                     "): element set " + normalize_name(text) +
                                     " is not defined; element sets: " + some_names(model_.elsets));
  return set->elements;
}

NodeSet& DeckReader::nset(const std::string& name, const SourceLoc& where) {
  NodeSet& set = model_.nsets[name];
  if (set.name.empty()) {
    set.name = name;
    set.where = where;
  }
  return set;
}

ElementSet& DeckReader::elset(const std::string& name, const SourceLoc& where) {
  ElementSet& set = model_.elsets[name];
  if (set.name.empty()) {
    set.name = name;
    set.where = where;
  }
  return set;
}

void DeckReader::finish() {
  const SourceLoc deck{model_.source, 0};
  if (in_step_)
    throw InputError(current_step().where,
                     "the deck ends inside this step: *END STEP is missing (truncated file?)");
  if (coupling_open_)
    throw InputError(model_.couplings.back().where,
                     "*COUPLING needs *KINEMATIC or *DISTRIBUTING right after it");
  const bool complete = completeness_ == DeckCompleteness::Complete;
  if (complete && model_.node_count() == 0)
    throw InputError(deck, "the deck defines no nodes (*NODE)");
  if (complete && model_.element_count() == 0)
    throw InputError(deck, "the deck defines no elements (*ELEMENT)");
  if (complete && model_.steps.empty())
    throw InputError(deck, "the deck has no analysis step (*STEP ... *END STEP)");
  check_field_kinds();  // includes the materials' *ELASTIC / *CONDUCTIVITY checks
  assign_sections();
  resolve_node_normals();
  resolve_contact_references();
  resolve_constraint_references();
  resolve_cyclic_references();
  resolve_penetration_references();
}

void DeckReader::assign_sections() {
  for (std::size_t s = 0; s < model_.sections.size(); ++s) {
    Section& section = model_.sections[s];
    const std::string keyword = section_keyword(section);
    section.material_index = model_.material_index(section.material);
    if (section.material_index < 0) {
      std::string names;
      for (const Material& m : model_.materials) names += (names.empty() ? "" : ", ") + m.name;
      throw InputError(section.where, keyword + " names material " + section.material +
                                          ", which is not defined; materials: " +
                                          (names.empty() ? "none are defined" : names));
    }
    if (!section.orientation.empty() && model_.orientations.count(section.orientation) == 0)
      throw InputError(section.where, "*SOLID SECTION names ORIENTATION=" + section.orientation +
                                          ", which is not defined; orientations: " +
                                          some_names(model_.orientations));
    const ElementSet* set = model_.find_elset(section.elset);
    if (!set)
      throw InputError(section.where,
                       keyword + " names element set " + section.elset +
                           ", which is not defined; element sets: " + some_names(model_.elsets));
    for (int e : set->elements) {
      Element& element = model_.elements[e];
      if (element.section >= 0) {
        const Section& other = model_.sections[element.section];
        throw InputError(section.where,
                         "element " + std::to_string(element.id) + " (in ELSET=" + section.elset +
                             ") already has a section (ELSET=" + other.elset + " at " +
                             other.where.str() + "); an element belongs to one section only");
      }
      // Beams take a *BEAM SECTION, shells a *SHELL SECTION, and only they do.
      if (const TElement* formulation = registry_.find(element.type)) {
        check_section_kind(section, element, *formulation);
        if (section.beam && section.beam->integration == BeamIntegration::Full &&
            formulation->rule(RuleKind::Full).size() == formulation->rule(RuleKind::Reduced).size())
          throw InputError(section.where, "*BEAM SECTION, INTEGRATION=FULL of element set " +
                                              section.elset + ": element " +
                                              std::to_string(element.id) + " is a " + element.type +
                                              ", whose name fixes reduced integration (CalculiX's "
                                              "R types); use " +
                                              element.type.substr(0, element.type.size() - 1) +
                                              " for full integration");
      }
      element.section = static_cast<int>(s);
    }
  }
  for (const Element& element : model_.elements)
    if (element.section < 0)
      throw InputError(element.where, "element " + std::to_string(element.id) + " (" +
                                          element.type +
                                          ") has no section: no *SOLID SECTION, *BEAM SECTION or "
                                          "*SHELL SECTION names an element set containing it");
}

}  // namespace styk::inp
