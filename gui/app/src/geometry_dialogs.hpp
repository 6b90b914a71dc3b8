// The dialogs of issue 7's view filter and geometry objects: View > Filter (element ids and types,
// session/element_filter.hpp) and Model > Plane / Line (session/geometry_objects.hpp).
#pragma once

#include <QWidget>
#include <functional>

#include "form_dialog.hpp"
#include "session/document.hpp"
#include "session/element_filter.hpp"

namespace styk::gui {

// Shows `current`; OK builds the filter (refusing bad range text or a filter nothing passes, in
// the dialog) and hands it to `apply`.
FormDialog* make_filter_dialog(const Model& model, const ElementDisplayFilter& current,
                               std::function<void(ElementDisplayFilter)> apply, QWidget* parent);

FormDialog* make_plane_dialog(Document& document, QWidget* parent);
FormDialog* make_line_dialog(Document& document, QWidget* parent);
FormDialog* make_shell_surface_dialog(Document& document, QWidget* parent);

}  // namespace styk::gui
