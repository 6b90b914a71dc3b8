// The model-creation dialogs (issue priority 3). Each returns a FormDialog wired to check its
// input (session/validation.hpp) and apply the edit to `document` as one undoable command on OK.
#pragma once

#include <QWidget>
#include <string>

#include "form_dialog.hpp"
#include "load_dialogs.hpp"
#include "session/document.hpp"

namespace styk::gui {

FormDialog* make_block_dialog(Document& document, QWidget* parent);
// A parametric builder of `styk mesh` (mesher::builder_catalogue()): replaces the model.
FormDialog* make_builder_dialog(Document& document, const std::string& builder, QWidget* parent);
FormDialog* make_material_dialog(Document& document, QWidget* parent);
FormDialog* make_section_dialog(Document& document, QWidget* parent);
FormDialog* make_step_dialog(Document& document, QWidget* parent);
// The same dialogs editing an existing entry (index into materials / sections / steps), filled
// with its values; -1 adds a new one.
FormDialog* make_material_dialog(Document& document, QWidget* parent, int material);
FormDialog* make_section_dialog(Document& document, QWidget* parent, int section);
FormDialog* make_step_dialog(Document& document, QWidget* parent, int step);

}  // namespace styk::gui
