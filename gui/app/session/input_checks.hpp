// The checks every model dialog shares (names, sets, steps, dofs, numbers) and how a meshed part
// joins the model. Each check throws InputError with the message the dialog shows in red.
#pragma once

#include <string>

#include "styk/core/model.hpp"

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
void check_finite(double value, const std::string& label);
// Node set, element set or surface named `name` exists already: refused with `hint`.
void check_set_names_free(const Model& model, const std::string& name);

// Appends `part` (node and element ids 1..n, e.g. from mesher::to_model) to `model` with ids after
// the largest existing ones; its node and element sets come along. Nodes are never merged with
// the model's: a part touching another one stays a separate body (a contact interface).
void append_part(Model& model, const Model& part);

}  // namespace styk::gui
