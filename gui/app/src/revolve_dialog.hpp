// The "Revolve" dialog (session/revolve.hpp): an r-z rectangle revolved about an axis, meshed
// with hexahedra and added to the model as one undoable edit.
#pragma once

#include <QWidget>

#include "form_dialog.hpp"
#include "session/document.hpp"

namespace styk::gui {

FormDialog* make_revolve_dialog(Document& document, QWidget* parent);

}  // namespace styk::gui
