// DeckReader: the state of reading one deck into a Model. The keyword table (deck_reader.cpp)
// checks where a keyword may appear and which parameters it takes, then calls one handler per
// keyword; the handlers live in mesh_keywords.cpp, property_keywords.cpp, beam_keywords.cpp,
// material_keywords.cpp, step_keywords.cpp, contact_keywords.cpp, constraint_keywords.cpp,
// thermal_keywords.cpp and scalar_keywords.cpp (and the other *_keywords.cpp files).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "card.hpp"
#include "card_source.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/inp/reader.hpp"

namespace styk::inp {

struct WrittenTerm;  // an *EQUATION term as written (constraint_keywords.cpp)

// The keyword that made a section ("*SOLID SECTION", "*BEAM SECTION", "*SHELL SECTION").
std::string section_keyword(const Section& section);
// Throws InputError at the section when its kind does not fit the element's formulation: beams
// take a *BEAM SECTION, shells a *SHELL SECTION, every other element a *SOLID SECTION
// (shell_keywords.cpp).
void check_section_kind(const Section& section, const Element& element,
                        const TElement& formulation);

class DeckReader {
 public:
  DeckReader(const std::string& path, const ElementRegistry& registry,
             DeckCompleteness completeness = DeckCompleteness::Complete);
  Model read();

  // Where a keyword may appear.
  // Interaction: inside a *SURFACE INTERACTION block (like Material for *MATERIAL).
  enum class Scope { Model, Material, Interaction, Step, Anywhere };
  enum class Value { None, Required, Optional };  // flag, NAME=value, either
  struct ParamSpec {
    const char* name;
    bool required;
    Value value;
  };
  using Handler = void (DeckReader::*)(const KeywordLine&);
  struct KeywordSpec {
    const char* name;
    Scope scope;
    std::vector<ParamSpec> params;
    Handler handler;
    bool takes_data;
  };
  static const std::vector<KeywordSpec>& keywords();

 private:
  void dispatch(const KeywordLine& kw);
  void check_parameters(const KeywordSpec& spec, const KeywordLine& kw) const;
  std::optional<DataLine> next_data_line();
  void finish();
  void assign_sections();

  // mesh_keywords.cpp
  void on_heading(const KeywordLine& kw);
  void on_node(const KeywordLine& kw);
  void on_element(const KeywordLine& kw);
  void on_nset(const KeywordLine& kw);
  void on_elset(const KeywordLine& kw);
  // property_keywords.cpp
  void on_material(const KeywordLine& kw);
  void on_density(const KeywordLine& kw);
  void on_solid_section(const KeywordLine& kw);
  // beam_keywords.cpp
  void on_beam_section(const KeywordLine& kw);
  void on_shell_section(const KeywordLine& kw);  // shell_keywords.cpp
  void check_shell_pressure(const Element& element, const SourceLoc& where) const;
  void on_normal(const KeywordLine& kw);  // normal_keywords.cpp
  // material_keywords.cpp
  void on_elastic(const KeywordLine& kw);
  void on_expansion(const KeywordLine& kw);
  // The rows of a material table: `count` constants (named `names` in messages) and an optional
  // temperature per row, 8 fields per line, temperatures increasing.
  // `lines`, when given, receives each row's first line.
  std::vector<MaterialTableRow> read_material_table(const KeywordLine& kw, std::size_t count,
                                                    const std::string& names,
                                                    std::vector<SourceLoc>* lines = nullptr);
  // step_keywords.cpp
  void on_step(const KeywordLine& kw);
  void on_static(const KeywordLine& kw);
  void on_end_step(const KeywordLine& kw);
  void on_boundary(const KeywordLine& kw);
  void on_cload(const KeywordLine& kw);
  void on_dload(const KeywordLine& kw);
  void on_node_print(const KeywordLine& kw);
  void on_el_print(const KeywordLine& kw);
  void on_node_file(const KeywordLine& kw);
  void on_el_file(const KeywordLine& kw);
  void read_output(const KeywordLine& kw, OutputRequest::Kind kind);
  // output_keywords.cpp
  void on_section_print(const KeywordLine& kw);
  void read_output_parameters(const KeywordLine& kw, OutputRequest& request) const;
  static std::vector<std::string> element_output_variables(OutputRequest::Kind kind);
  void complete_element_variables(const KeywordLine& kw, OutputRequest& request) const;
  // contact_keywords.cpp
  void on_surface(const KeywordLine& kw);
  void on_surface_interaction(const KeywordLine& kw);
  void on_surface_behavior(const KeywordLine& kw);
  void on_friction(const KeywordLine& kw);
  void on_contact_pair(const KeywordLine& kw);
  void on_clearance(const KeywordLine& kw);
  void on_contact_print(const KeywordLine& kw);
  // Names that may be defined after the line using them, checked once the deck is complete.
  void resolve_contact_references();
  // constraint_keywords.cpp
  void on_orientation(const KeywordLine& kw);
  void on_transform(const KeywordLine& kw);
  void on_equation(const KeywordLine& kw);
  // Adds copy `copy` of an equation whose terms may name node sets (constraint_keywords.cpp).
  void add_equation(const std::vector<WrittenTerm>& terms, std::size_t copy,
                    const SourceLoc& where);
  // load_keywords.cpp
  void read_body_load(const DataLine& line, const std::string& label);  // *DLOAD GRAV, CENTRIF
  void on_dsload(const KeywordLine& kw);
  void read_initial_stresses(const KeywordLine& kw);  // *INITIAL CONDITIONS, TYPE=STRESS
  void on_change_solid_section(const KeywordLine& kw);
  // tie_keywords.cpp (*TIE: tied contact)
  void on_tie(const KeywordLine& kw);
  void read_tied_contact(const KeywordLine& kw);
  // coupling_keywords.cpp
  void on_coupling(const KeywordLine& kw);
  void on_coupling_kind(const KeywordLine& kw);  // *KINEMATIC, *DISTRIBUTING
  void on_mpc(const KeywordLine& kw);
  void on_pretension_section(const KeywordLine& kw);
  void resolve_constraint_references();
  // The dof of a *CLOAD line (field 2): a force 1..3 or a moment 4..6 (beam nodes, a distributing
  // coupling's reference node; the solver checks that the node takes it).
  int load_dof(const DataLine& line) const;
  // cyclic_keywords.cpp (*TIE, CYCLIC SYMMETRY)
  void read_cyclic_tie(const KeywordLine& kw);
  void on_cyclic_symmetry_model(const KeywordLine& kw);
  void resolve_cyclic_references();
  // normal_keywords.cpp: the normals of *NODE lines (Abaqus' fields 5-7) become *NORMAL entries
  // of every shell at the node once the elements are known, ahead of the deck's *NORMAL lines.
  void resolve_node_normals();
  // penetration_keywords.cpp
  void on_pressure_penetration(const KeywordLine& kw);
  void resolve_penetration_references();
  // thermal_keywords.cpp
  void on_initial_conditions(const KeywordLine& kw);
  void on_temperature(const KeywordLine& kw);
  // scalar_keywords.cpp
  void on_heat_transfer(const KeywordLine& kw);
  void on_coupled_thermal_electrical(const KeywordLine& kw);
  void on_conductivity(const KeywordLine& kw);  // also *ELECTRICAL CONDUCTIVITY
  void on_cflux(const KeywordLine& kw);
  void on_cecur(const KeywordLine& kw);
  void on_dflux(const KeywordLine& kw);
  void read_scalar_procedure(const KeywordLine& kw, StepKind kind);
  void read_scalar_loads(const KeywordLine& kw, int dof);
  // Once the deck is complete: boundary dofs and loads match their steps' procedures, and the
  // materials have what the procedures need.
  void check_field_kinds();

  // Helpers shared by the handlers.
  // Node indices named by one field: a node id or the name of a node set.
  std::vector<int> nodes_of(const DataLine& line, std::size_t field, const std::string& what);
  std::vector<int> elements_of(const DataLine& line, std::size_t field, const std::string& what);
  int node_by_id(Id id, const SourceLoc& where, const std::string& context) const;
  int element_by_id(Id id, const SourceLoc& where, const std::string& context) const;
  NodeSet& nset(const std::string& name, const SourceLoc& where);
  ElementSet& elset(const std::string& name, const SourceLoc& where);
  std::string set_name(const KeywordLine& kw, const char* param) const;
  Material& current_material(const KeywordLine& kw);
  Step& current_step() { return model_.steps.back(); }
  void expect_fields(const DataLine& line, std::size_t min, std::size_t max,
                     const std::string& layout) const;
  std::optional<DataLine> single_data_line(const KeywordLine& kw, bool required,
                                           const std::string& layout);
  PressureOverclosure read_pressure_overclosure(const KeywordLine& kw);

  CardSource source_;
  const ElementRegistry& registry_;
  DeckCompleteness completeness_;
  Model model_;
  int material_ = -1;        // the *MATERIAL block being read, -1 outside one
  std::string interaction_;  // the *SURFACE INTERACTION block being read, empty outside one
  // *CLEARANCE lines, matched with their contact pair when the deck is complete.
  struct PendingClearance {
    std::string slave, master;
    double value = 0.0;
    SourceLoc where;
  };
  std::vector<PendingClearance> clearances_;
  bool in_step_ = false;
  bool coupling_open_ = false;  // a *COUPLING waits for its *KINEMATIC / *DISTRIBUTING
  std::string last_keyword_;    // for "takes no data lines" messages
  // Where each node was defined (file index into files_, line), for duplicate-id messages.
  std::vector<std::pair<int, int>> node_lines_;
  std::vector<std::string> files_;
  struct NodeNormal {  // fields 5-7 of a *NODE line
    int node = 0;
    Vec3 direction{};
    SourceLoc where;
  };
  std::vector<NodeNormal> node_normals_;
};

// "A, B, C and 4 more" or "none are defined" for messages.
template <class Map>
std::string some_names(const Map& sets) {
  if (sets.empty()) return "none are defined";
  std::string out;
  std::size_t shown = 0;
  for (const auto& kv : sets) {
    if (shown == 8) return out + " and " + std::to_string(sets.size() - shown) + " more";
    out += (shown ? ", " : "") + kv.first;
    ++shown;
  }
  return out;
}

}  // namespace styk::inp
