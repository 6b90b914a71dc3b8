// Helpers the model dialogs share: the model's names for choice lists, and several numbers in
// one text field ("0 0 1", commas or spaces), refused with InputError like single fields.
#pragma once

#include <QStringList>
#include <string>
#include <vector>

#include "form_dialog.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

QStringList node_set_names(const Model& model);
QStringList element_set_names(const Model& model);
QStringList surface_names(const Model& model);
QStringList material_names(const Model& model);
// "1 HEAT", "2 PUSH", ...; with `model_level` first `model_level_text` ("0 (all steps)").
QStringList step_names(const Model& model, bool model_level,
                       const QString& model_level_text = "0 (all steps)");
// The 0-based step of a step_names() entry, -1 for the model-level one.
int step_index(const std::string& entry);

std::vector<double> numbers(const FormDialog& f, const QString& key, const QString& label,
                            int count);
std::vector<int> whole_numbers(const FormDialog& f, const QString& key, const QString& label,
                               int count);

}  // namespace styk::gui
