// Editing and deleting what the model tree lists: an Entry names one item (a material, a step's
// loads, a contact pair, a set, ...); delete_command() removes it undoably or refuses with the
// reason when something still uses it (a material a section names, an element set with a
// section, a surface of a contact pair, a node set a *TRANSFORM names, an orientation an
// anisotropic friction names); the *_edit_command()s
// replace an entry with what its dialog now says.
#pragma once

#include <memory>
#include <string>

#include "session/commands.hpp"
#include "session/validation.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

enum class EntryKind {
  Material,         // index into materials
  Section,          // index into sections
  Step,             // index into steps (with everything in it)
  ModelBoundaries,  // boundary conditions held in every step
  StepBoundaries,   // index = the step
  StepCloads,
  StepDloads,
  StepTemperatures,
  InitialTemperatures,
  StepFluxes,   // index = the step: its *CFLUX / *CECUR nodal heat flows or currents
  ContactPair,  // index into contact_pairs (its interaction goes too when no other pair uses it)
  Equation,     // index into equations
  Transform,    // index into transforms
  NodeSet,      // name
  ElementSet,   // name
  Surface,      // name
  StepDfluxes,  // index = the step: its *DFLUX face fluxes (heat transfer steps)
  Orientation,  // name (refused while an anisotropic friction names it)
};

struct Entry {
  EntryKind kind = EntryKind::Material;
  int index = -1;
  std::string name;
  // For the per-node lists (boundary conditions, loads, pressures, face fluxes, temperatures, nodal
  // fluxes): -1 the
  // whole list, otherwise one group of it (session/load_groups.hpp: what one dialog made).
  int item = -1;
};

// Throws InputError with the reason when the entry cannot go (or does not exist).
std::unique_ptr<Command> delete_command(const Model& model, const Entry& entry);

std::unique_ptr<Command> material_edit_command(const Model& model, int material,
                                               const MaterialInput& input);
MaterialInput material_input_of(const Model& model, int material);
// A section keeps its element set; the material changes.
std::unique_ptr<Command> section_edit_command(const Model& model, int section,
                                              const std::string& material);
std::unique_ptr<Command> step_edit_command(const Model& model, int step, const StepInput& input);

}  // namespace styk::gui
