// Dialogs for contact, thermal loads, constraints and derived node sets (session/
// contact_input.hpp, thermal_input.hpp, constraint_input.hpp): each checks in the dialog and
// applies one undoable edit on OK.
#pragma once

#include <QWidget>
#include <string>

#include "form_dialog.hpp"
#include "session/document.hpp"
#include "session/entry_edits.hpp"

namespace styk::gui {

// `pair` >= 0 edits that contact pair (fields filled from it).
FormDialog* make_contact_dialog(Document& document, QWidget* parent, int pair = -1);
FormDialog* make_new_contact_dialog(Document& document, QWidget* parent);
// *INITIAL CONDITIONS, TYPE=TEMPERATURE or a step's *TEMPERATURE on a node set.
FormDialog* make_initial_temperature_dialog(Document& document, QWidget* parent);
FormDialog* make_temperature_dialog(Document& document, QWidget* parent);
FormDialog* make_equation_dialog(Document& document, QWidget* parent);
FormDialog* make_transform_dialog(Document& document, QWidget* parent);
// Editing: a group of initial or step temperatures (session/load_groups.hpp), equation /
// transform `index` (filled with its values).
FormDialog* make_temperature_dialog(Document& document, QWidget* parent, const Entry& group);
FormDialog* make_equation_dialog(Document& document, QWidget* parent, int equation);
FormDialog* make_transform_dialog(Document& document, QWidget* parent, int transform);
FormDialog* make_common_nodes_dialog(Document& document, QWidget* parent);
// *ORIENTATION: a named local system (rectangular or cylindrical, points a and b) for anisotropic
// friction; `name` non-empty edits that orientation.
FormDialog* make_orientation_dialog(Document& document, QWidget* parent);
FormDialog* make_orientation_dialog(Document& document, QWidget* parent, const std::string& name);

}  // namespace styk::gui
