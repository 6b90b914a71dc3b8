// What double-click / "Edit..." on a model tree entry opens: the dialog of that entry filled
// with its values (materials, sections, steps, contact pairs). Other entries (sets, the
// per-dof boundary condition and load lists, equations, transforms) are deleted and added again.
#pragma once

#include <QWidget>

#include "form_dialog.hpp"
#include "session/document.hpp"
#include "session/entry_edits.hpp"

namespace styk::gui {

// nullptr when the entry has no edit dialog.
FormDialog* make_entry_dialog(Document& document, const Entry& entry, QWidget* parent);

}  // namespace styk::gui
