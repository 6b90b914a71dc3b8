// The checks every model dialog shares (names, sets, steps, dofs, numbers) and how a meshed part
// joins the model. Each check throws InputError with the message the dialog shows in red.
#pragma once

#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::gui {

[[noreturn]] void refuse(const std::string& message);

// Set and material names go into the deck unquoted: a letter, then letters, digits, _ - .
void check_name(const std::string& name, const std::string& what);
// An existing, non-empty node set (name case-insensitive).
const NodeSet& existing_nset(const Model& model, const std::string& name);
// An existing element-face surface with faces.
const Surface& existing_surface(const Model& model, const std::string& name);
// step < 0 means "every step" where `model_level_allowed`; otherwise a 0-based existing step.
void check_step(const Model& model, int step, bool model_level_allowed);
void check_dof(int dof, const std::string& label);
// The dofs a step of `kind` takes: 1..3 displacements and 4..6 rotations (static; rotations at
// nodes of beams and shells, which the solver checks), 11 temperature (steady heat), 9 electric
// potential (electric conduction).
bool dof_fits_step(int dof, StepKind kind);
// A dof of a boundary condition or load in step `step` (< 0: held in every step, so it must fit
// every step), refused with what the step takes.
void check_field_dof(const Model& model, int step, int dof, const std::string& label);
// Whether a dof is a scalar field's (11 temperature, 9 electric potential): its loads are fluxes
// (*CFLUX, *CECUR) and a boundary condition on it is one dof.
bool is_flux_dof(int dof);
// "static", "heat transfer", "electric conduction": the step dialog's names of a StepKind.
std::string step_kind_name(StepKind kind);
// The StepKind of a step_kind_name(); InputError for another text.
StepKind step_kind_of(const std::string& name);
void check_finite(double value, const std::string& label);
// Node set, element set or surface named `name` exists already: refused with `hint`.
void check_set_names_free(const Model& model, const std::string& name);

// Appends `part` (node and element ids 1..n, e.g. from mesher::to_model) to `model` with ids after
// the largest existing ones; its node and element sets come along. Nodes are never merged with
// the model's: a part touching another one stays a separate body (a contact interface).
void append_part(Model& model, const Model& part);

// append_part of a meshed part plus, for each name of `surfaces`, the mesh's surface of that name
// (faces sorted by element, then face) and, when `material` is not empty, a section of that
// material on element set `elset`. Mesh block and revolve both end this way.
void append_meshed_part(Model& model, const mesher::Mesh& mesh,
                        const std::vector<std::string>& surfaces, const std::string& elset,
                        const std::string& material);

}  // namespace styk::gui
