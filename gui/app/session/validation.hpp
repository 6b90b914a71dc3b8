// What the model-creation dialogs ask for, how it is checked, and the edit command it becomes.
// Each check_*() throws InputError with a message for the dialog (which then stays open); each
// *_command() checks first, so no invalid edit reaches the model.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "session/commands.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

// Text fields of the dialogs: a number, or InputError "LABEL: 'text' is not a number".
double parse_real(const std::string& text, const std::string& label);
int parse_integer(const std::string& text, const std::string& label);

// "Mesh block": a hexahedral block meshed with mesher/ and appended to the model (new node and
// element ids follow the largest existing ones). The element set NAME receives the elements; node
// sets NAME_XMIN, NAME_XMAX, NAME_YMIN, ... the nodes of the six block sides (the sides of the
// map: xi = -1 is XMIN, eta = -1 YMIN, zeta = -1 ZMIN).
struct BlockInput {
  bool use_corners = false;    // true: the 8 corners (C3D8 order); false: origin + size box
  std::array<Vec3, 8> corners{};
  Vec3 origin{0, 0, 0};
  Vec3 size{1, 1, 1};
  std::array<int, 3> divisions{4, 1, 1};
  std::array<double, 3> grading{1, 1, 1};  // last / first element length per direction
  // C3D8, C3D20, or C3D21 / C3D28: C3D20 whose layer of elements on side `layer_side` becomes
  // the thesis' contact hexahedra.
  std::string type = "C3D20";
  std::string layer_side = "ZMAX";  // XMIN, XMAX, YMIN, YMAX, ZMIN, ZMAX
  std::string name = "BLOCK";
  std::string material;  // non-empty: also a solid section of the new set with this material
};
void check_block(const BlockInput& input, const Model& model, const ElementRegistry& registry);
// The model with the block appended (throws InputError like check_block, or for a map the mesher
// refuses, e.g. left-handed corners).
Model model_with_block(const Model& model, const BlockInput& input,
                       const ElementRegistry& registry);
std::unique_ptr<Command> block_command(const Model& model, const BlockInput& input,
                                       const ElementRegistry& registry);

struct MaterialInput {
  std::string name;
  double young = 210000.0;  // 0: no *ELASTIC (only with a conductivity: a heat/electric material)
  double poisson = 0.3;
  double density = 0.0;  // 0: not given
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
