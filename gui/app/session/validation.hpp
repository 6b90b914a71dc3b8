// What the model-creation dialogs ask for, how it is checked, and the edit command it becomes.
// Each check_*() throws InputError with a message for the dialog (which then stays open); each
// *_command() checks first, so no invalid edit reaches the model.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "session/block_input.hpp"  // the "Mesh block" dialog (BlockInput, block_command)
#include "session/commands.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

// Text fields of the dialogs: a number, or InputError "LABEL: 'text' is not a number".
double parse_real(const std::string& text, const std::string& label);
int parse_integer(const std::string& text, const std::string& label);

struct MaterialInput {
  std::string name;
  double young = 210000.0;  // 0: no *ELASTIC (only with a conductivity: a heat/electric material)
  double poisson = 0.3;
  double density = 0.0;    // 0: not given
  double expansion = 0.0;  // *EXPANSION mean coefficient (reference 0); 0: not given
  // *CONDUCTIVITY / *ELECTRICAL CONDUCTIVITY: empty = not given, 1 value = isotropic, 3 values =
  // orthotropic k11 k22 k33 in global axes; each > 0.
  std::vector<double> conductivity{};
  std::vector<double> electrical_conductivity{};
};
std::unique_ptr<Command> material_command(const Model& model, const MaterialInput& input);
// The material as the dialog asks for it (checks name clashes against `model` except with the
// material at index `replacing`, -1 for a new one).
Material checked_material(const Model& model, const MaterialInput& input, int replacing = -1);

struct SectionInput {
  std::string elset;
  std::string material;
};
std::unique_ptr<Command> section_command(const Model& model, const SectionInput& input);

struct StepInput {
  std::string name = "STEP";
  double initial_increment = 1.0;
  double total_time = 1.0;
  // Static (*STATIC), steady heat (*HEAT TRANSFER, STEADY STATE: temperature, dof 11) or electric
  // conduction (*COUPLED THERMAL-ELECTRICAL, STEADY STATE: potential, dof 9).
  StepKind kind = StepKind::Static;
};
std::unique_ptr<Command> step_command(const Model& model, const StepInput& input);

// Prescribed value of dofs first..last on every node of a node set, either for the whole analysis
// (step < 0) or inside step `step` (0-based): displacements 1..3 in static steps, the temperature
// (11) in heat and the potential (9) in electric steps (first = last then).
struct BoundaryInput {
  std::string nset;
  int first_dof = 1;
  int last_dof = 3;
  double value = 0.0;
  int step = -1;
};
std::unique_ptr<Command> boundary_command(const Model& model, const BoundaryInput& input);

// *CLOAD: `value` in direction dof on every node of the set (total = value x nodes when
// `split` is false; with `split` the value is the total, divided equally among the nodes).
// In a heat step dof 11 is a nodal heat flow (*CFLUX), in an electric step dof 9 a nodal current
// (*CECUR); both go to Step::cfluxes.
struct CloadInput {
  std::string nset;
  int dof = 3;
  double value = 0.0;
  bool split = false;
  int step = 0;
};
std::unique_ptr<Command> cload_command(const Model& model, const CloadInput& input);

// *DLOAD pressure on the faces of a surface (Model::surfaces, element faces), or on face
// `face` (1..6) of every element of an element set when `surface` is empty.
struct PressureInput {
  std::string surface;
  std::string elset;
  int face = 1;
  double magnitude = 0.0;
  int step = 0;
};
std::unique_ptr<Command> pressure_command(const Model& model, const PressureInput& input);

}  // namespace styk::gui
