// The per-node lists of the model (boundary conditions, concentrated loads, nodal heat flows /
// currents, pressures, face fluxes, temperatures) hold one entry per node and dof (or face), as
// the deck does; a dialog made many of them at once. A group is what one dialog made, found again
// from the list: the entries of one value (and, for boundary conditions, a run of consecutive dofs
// with the same nodes), with the node set or surface whose members they are when one matches. The
// model tree shows the groups; each can be edited (its dialog filled from the group) or deleted, as
// one undoable command, with the add dialogs' checks.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "session/commands.hpp"
#include "session/entry_edits.hpp"
#include "session/flux_input.hpp"
#include "session/thermal_input.hpp"
#include "session/validation.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

struct NodeGroup {
  std::vector<int> nodes;  // node indices, ascending
  int first_dof = 0;       // boundary conditions: dofs first..last; loads: first = last = dof;
  int last_dof = 0;        // temperatures: 0
  double value = 0.0;
  std::string nset;            // the node set holding exactly these nodes; empty when none does
  std::vector<int> positions;  // where the group's entries are in the list
};

struct FaceGroup {
  std::vector<SurfaceFace> faces;  // by (element, face)
  double magnitude = 0.0;
  std::string surface;  // the surface holding exactly these faces, or empty
  std::string elset;    // else: the element set whose elements carry them all on face `face`
  int face = 0;
  std::vector<int> positions;
};

// Whether the entry stands for a per-node list (or a group of one).
bool is_load_list(EntryKind kind);
// The groups of the list `entry` names (entry.kind + entry.index = the step; item ignored).
std::vector<NodeGroup> node_groups(const Model& model, const Entry& entry);
// StepDloads (pressures) or StepDfluxes (face fluxes).
std::vector<FaceGroup> face_groups(const Model& model, const Entry& entry);
// One line per group for the model tree, e.g. "INNER: dof 11 = 100", "12 nodes: dofs 1-3 = 0",
// "TOP: pressure 5", "OUTER: flux 3".
std::vector<std::string> group_labels(const Model& model, const Entry& entry);

// What the group's dialog shows (nset / surface empty: "the same nodes / faces as now").
BoundaryInput boundary_input_of(const Model& model, const Entry& group);
CloadInput cload_input_of(const Model& model, const Entry& group);  // split = false: per node
PressureInput pressure_input_of(const Model& model, const Entry& group);
FluxInput flux_input_of(const Model& model, const Entry& group);
TemperatureInput temperature_input_of(const Model& model, const Entry& group);

// Replace group `entry.item` of the list by what the dialog says, checked as the add dialogs
// check (an empty set name keeps the group's nodes / faces). The step may change: the group
// moves to the other step's list (a load with dof 11 or 9 goes to the step's flux list).
std::unique_ptr<Command> boundary_edit_command(const Model& model, const Entry& group,
                                               const BoundaryInput& input);
std::unique_ptr<Command> cload_edit_command(const Model& model, const Entry& group,
                                            const CloadInput& input);
std::unique_ptr<Command> pressure_edit_command(const Model& model, const Entry& group,
                                               const PressureInput& input);
std::unique_ptr<Command> temperature_edit_command(const Model& model, const Entry& group,
                                                  const TemperatureInput& input);
// A face-flux group: the step must be a heat transfer step (flux_input.hpp).
std::unique_ptr<Command> flux_edit_command(const Model& model, const Entry& group,
                                           const FluxInput& input);
// Removes group `entry.item` of the list.
std::unique_ptr<Command> group_delete_command(const Model& model, const Entry& group);

}  // namespace styk::gui
