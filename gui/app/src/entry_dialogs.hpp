// What double-click / "Edit..." on a model tree entry opens: the dialog of that entry filled
// with its values — materials, sections, steps, contact pairs, one group of boundary conditions,
// loads, fluxes, pressures or temperatures (session/load_groups.hpp), equations, transforms, and
// node sets / element sets / surfaces (a new name, members from the selection in the view).
#pragma once

#include <QWidget>

#include "form_dialog.hpp"
#include "session/document.hpp"
#include "session/entry_edits.hpp"
#include "session/selection.hpp"

namespace styk::gui {

// Whether make_entry_dialog() has a dialog for the entry (a whole list has none: its groups do).
bool has_entry_dialog(const Entry& entry);
// nullptr when the entry has no edit dialog. `selection` (the view's, read when OK is pressed)
// gives a set's new members; it must outlive the dialog.
FormDialog* make_entry_dialog(Document& document, const Entry& entry, const Selection& selection,
                              QWidget* parent);
// The set dialog alone (a NodeSet, ElementSet or Surface entry).
FormDialog* make_set_dialog(Document& document, const Entry& set, const Selection& selection,
                            QWidget* parent);

}  // namespace styk::gui
